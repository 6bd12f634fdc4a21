// The ImGui panel: a slider per parameter (glman's "a uniform with a range becomes a slider").
#include "common/window/window_panel.h"
#include "common/window/legend_imgui.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <string>

namespace gsv {
namespace {

class ImGuiPanel final : public WindowPanel {
public:
    ImGuiPanel(GLFWwindow* window, GlVersion version) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini dropped into the student's working directory
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        const std::string glsl = "#version " + std::to_string(std::min(version.glsl(), 410));
        ImGui_ImplOpenGL3_Init(glsl.c_str());
    }
    ~ImGuiPanel() override {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }

    bool draw(PanelState& state) override {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        bool changed = false;
        ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowBgAlpha(0.55f);
        ImGui::SetNextWindowCollapsed(false, ImGuiCond_FirstUseEver);
        // Narrow and translucent: the lab's image is what the room is looking at.
        ImGui::Begin(state.heading.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::SetWindowFontScale(0.85f);
        ImGui::PushItemWidth(110.0f);
        ImGui::Text("%.2f ms render (glFinish), %.1f fps", state.render_ms,
                    state.frame_ms > 0 ? 1000.0 / state.frame_ms : 0.0);
        ImGui::TextDisabled("%s", state.gl.substr(0, state.gl.find(',')).c_str());
        ImGui::Separator();
        Params& params = state.params;
        int index = 0;
        for (const auto& spec : params.specs()) {
            ImGui::PushID(index);
            const bool selected = index == state.selected;
            std::string label = spec.name + (spec.sweep_values.empty() ? "" : " (accuracy)");
            if (selected) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.3f, 1.0f));
            switch (spec.type) {
            case ParamType::Float: {
                float v = params.get_float(spec.name);
                if (ImGui::SliderFloat(label.c_str(), &v, static_cast<float>(spec.min), static_cast<float>(spec.max))) {
                    params.set(spec.name, std::to_string(v));
                    changed = true;
                }
                break;
            }
            case ParamType::Int: {
                int v = params.get_int(spec.name);
                if (ImGui::SliderInt(label.c_str(), &v, static_cast<int>(spec.min), static_cast<int>(spec.max))) {
                    params.set(spec.name, std::to_string(v));
                    changed = true;
                }
                break;
            }
            case ParamType::Bool: {
                bool v = params.get_bool(spec.name);
                if (ImGui::Checkbox(label.c_str(), &v)) {
                    params.set(spec.name, v ? "on" : "off");
                    changed = true;
                }
                break;
            }
            case ParamType::Choice: {
                const std::string current = params.get_choice(spec.name);
                if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
                    for (const auto& choice : spec.choices)
                        if (ImGui::Selectable(choice.c_str(), choice == current)) {
                            params.set(spec.name, choice);
                            changed = true;
                        }
                    ImGui::EndCombo();
                }
                break;
            }
            case ParamType::File:
                ImGui::Text("%s: %s", label.c_str(), params.get_file(spec.name).c_str());
                break;
            case ParamType::Vec3: {
                glm::vec3 v = params.get_vec3(spec.name);
                if (ImGui::SliderFloat3(label.c_str(), &v.x, static_cast<float>(spec.min), static_cast<float>(spec.max))) {
                    params.set(spec.name, std::to_string(v.x) + "," + std::to_string(v.y) + "," + std::to_string(v.z));
                    changed = true;
                }
                break;
            }
            }
            if (selected) ImGui::PopStyleColor();
            if (ImGui::IsItemHovered() && !spec.help.empty()) ImGui::SetTooltip("%s", spec.help.c_str());
            if (ImGui::IsItemActivated()) state.selected = index;
            ImGui::PopID();
            ++index;
        }
        if (state.legend) {
            ImGui::Separator();
            draw_legend_imgui(*state.legend);
        }
        if (!state.status.empty()) {
            ImGui::Separator();
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
            ImGui::TextWrapped("%s", state.status.c_str());
            ImGui::PopStyleColor();
        }
        ImGui::TextDisabled("H: keys  S: screenshot  P: command line");
        ImGui::PopItemWidth();
        ImGui::End();
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        return changed;
    }
    bool wants_mouse() const override { return ImGui::GetIO().WantCaptureMouse; }
    bool wants_keyboard() const override { return ImGui::GetIO().WantCaptureKeyboard; }
};

}  // namespace

std::unique_ptr<WindowPanel> make_window_panel(GLFWwindow* window, GlVersion version) {
    return std::make_unique<ImGuiPanel>(window, version);
}

}  // namespace gsv
