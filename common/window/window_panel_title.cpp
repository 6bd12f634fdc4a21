// Without Dear ImGui the panel is the window title: frame time and the selected parameter.
#include "common/window/window_panel.h"

#include <GLFW/glfw3.h>

#include <cstdio>

namespace gsv {
namespace {

class TitlePanel final : public WindowPanel {
public:
    explicit TitlePanel(GLFWwindow* window) : window_(window) {}
    bool draw(PanelState& state, const PanelPlacement&) override {
        const auto& spec = state.params.specs()[static_cast<std::size_t>(state.selected)];
        const std::string inactive = state.params.inactive_reason(spec.name);
        char title[640];
        std::snprintf(title, sizeof title, "%s%s%s | %.2f ms render, %.1f fps%s%s | %s = %s%s%s  (H: keys)%s%s",
                      state.heading.c_str(), state.view.empty() && state.inspected.empty() ? "" : " | ",
                      (state.inspected.empty() ? state.view : "inspecting " + state.inspected).c_str(), state.render_ms,
                      state.frame_ms > 0 ? 1000.0 / state.frame_ms : 0.0, state.ceiling.empty() ? "" : ", ",
                      state.ceiling.c_str(), spec.name.c_str(),
                      state.params.get_text(spec.name).c_str(), inactive.empty() ? "" : ", no effect: ", inactive.c_str(),
                      state.status.empty() ? "" : " | ", state.status.substr(0, 80).c_str());
        glfwSetWindowTitle(window_, title);
        return false;
    }

private:
    GLFWwindow* window_;
};

}  // namespace

#if !GSV_HAVE_IMGUI
int default_panel_width() { return 0; }

std::unique_ptr<WindowPanel> make_window_panel(GLFWwindow* window, Profile, GlVersion) {
    return std::make_unique<TitlePanel>(window);
}
#endif

}  // namespace gsv
