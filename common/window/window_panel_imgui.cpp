// The ImGui panel: a slider per parameter (glman's "a uniform with a range becomes a slider"), docked in its own
// column beside the picture so that nothing covers what the room is looking at, in a scalable font at whole pixel
// sizes so that digits stay legible on a projector.
#include "common/core/error.h"
#include "common/gl/gl.h"
#include "common/image/ui_font.h"
#include "common/window/legend_imgui.h"
#include "common/window/window_panel.h"

#include <GLFW/glfw3.h>
// Debian's libimgui-dev keeps the bindings in backends/; vcpkg's port puts them beside imgui.h.
#if __has_include(<backends/imgui_impl_glfw.h>)
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#else
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#endif
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace gsv {
namespace {

constexpr float kFontPixels = 16;      // at a content scale of 1
constexpr float kPanelEms = 24;        // the panel's width in font heights
constexpr float kSliderShare = 0.45f;  // of the panel's width; the name goes beside it

class ImGuiPanel final : public WindowPanel {
public:
    ImGuiPanel(GLFWwindow* window, Profile profile, GlVersion version) : es_(profile == Profile::Es) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;  // no imgui.ini dropped into the student's working directory
        ImGui::StyleColorsDark();
        load_font(window);
        ImGuiStyle& style = ImGui::GetStyle();
        style.WindowRounding = 0;
        style.GrabMinSize = 6;  // a thin handle beside the value, not over its digits
        style.Colors[ImGuiCol_SliderGrab].w = 0.45f;
        style.Colors[ImGuiCol_SliderGrabActive].w = 0.6f;
        style.ScaleAllSizes(ui_scale_);
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        // ImGui's backend has shaders for GLSL 1.30 to 4.10 and for GLSL ES 3.00; it picks one by this line.
        const int glsl = es_ ? 300 : std::min(version.glsl(), 410);
        const std::string version_line = "#version " + std::to_string(glsl) + (es_ ? " es" : "");
        ImGui_ImplOpenGL3_Init(version_line.c_str());
    }
    ~ImGuiPanel() override {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }

    int width() const override { return static_cast<int>(std::lround(kPanelEms * kFontPixels * ui_scale_)); }

    bool draw(PanelState& state, const PanelPlacement& placement) override {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(placement.x, 0));
        ImGui::SetNextWindowSize(ImVec2(placement.width, placement.height));
        ImGui::Begin("##panel", nullptr,
                     ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
        ImGui::PushItemWidth(placement.width * kSliderShare);
        ImGui::TextUnformatted(state.heading.c_str());
        ImGui::Text("%.2f ms render (glFinish), %.1f fps", state.render_ms,
                    state.frame_ms > 0 ? 1000.0 / state.frame_ms : 0.0);
        if (!state.ceiling.empty()) ImGui::TextWrapped("%s", state.ceiling.c_str());
        ImGui::TextDisabled("%s", state.gl.c_str());
        if (!state.view.empty() || !state.inspected.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.85f, 1.0f, 1.0f));
            ImGui::TextWrapped("showing: %s", (state.inspected.empty() ? state.view : state.inspected).c_str());
            ImGui::PopStyleColor();
        }
        // The legend before the parameters: what the colours mean stays in view however long the list.
        if (state.legend) {
            ImGui::Separator();
            draw_legend_imgui(*state.legend);
        }
        ImGui::Separator();
        const bool changed = draw_parameters(state);
        draw_inspector(state);
        if (!state.status.empty()) {
            ImGui::Separator();
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
            ImGui::TextWrapped("%s", state.status.c_str());
            ImGui::PopStyleColor();
        }
        ImGui::Separator();
        ImGui::TextDisabled("U: hide panel  H: keys  S: screenshot");
        ImGui::TextDisabled("V: student/reference/split/difference");
        if (!state.stages.empty()) ImGui::TextDisabled("I: the next stage image (visual debugging)");
        ImGui::PopItemWidth();
        ImGui::End();
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        // Debian builds ImGui's GL backend for desktop GL: on ES it saves and restores state ES does not have
        // (glPolygonMode, GL_PRIMITIVE_RESTART), which only sets GL_INVALID_ENUM / _OPERATION and draws the panel
        // all the same. Those errors are the backend's, not the lab's: cleared here so the kit's checks see only its own.
        if (es_)
            while (glGetError() != GL_NO_ERROR) {
            }
        return changed;
    }
    bool wants_mouse() const override { return ImGui::GetIO().WantCaptureMouse; }
    bool wants_keyboard() const override { return ImGui::GetIO().WantCaptureKeyboard; }

private:
    bool es_ = false;
    // Whole pixels: a font rasterised at a fractional scale loses its decimal points. On a display whose framebuffer
    // is larger than its window (macOS Retina) the font is rasterised at the framebuffer's density and drawn at
    // window size; elsewhere the monitor's content scale sets the size.
    void load_font(GLFWwindow* window) {
        ImGuiIO& io = ImGui::GetIO();
        int window_w = 0, window_h = 0, framebuffer_w = 0, framebuffer_h = 0;
        glfwGetWindowSize(window, &window_w, &window_h);
        glfwGetFramebufferSize(window, &framebuffer_w, &framebuffer_h);
        const float density = window_w > 0 ? static_cast<float>(framebuffer_w) / static_cast<float>(window_w) : 1.0f;
        float content_x = 1, content_y = 1;
        glfwGetWindowContentScale(window, &content_x, &content_y);
        ui_scale_ = density > 1.01f ? 1.0f : std::max(1.0f, content_x);
        const float raster = density > 1.01f ? density : 1.0f;
        const float pixels = std::round(kFontPixels * ui_scale_ * raster);
        std::string why;
        try {
            const std::filesystem::path font = find_ui_font();
            if (io.Fonts->AddFontFromFileTTF(font.string().c_str(), pixels)) {
                io.FontGlobalScale = 1.0f / raster;
                return;
            }
            why = font.string() + " would not load";
        } catch (const Error& e) {
            why = e.what();
        }
        // ImGui's own bitmap font, at a whole multiple of its 13 px: crisp, if small.
        std::fprintf(stderr, "panel: %s; using ImGui's bitmap font\n", why.c_str());
        ImFontConfig config;
        config.SizePixels = 13.0f * std::max(1.0f, std::round(ui_scale_ * raster));
        io.Fonts->AddFontDefault(&config);
        io.FontGlobalScale = 1.0f / raster;
    }

    bool draw_parameters(PanelState& state) {
        bool changed = false;
        Params& params = state.params;
        int index = 0;
        for (const auto& spec : params.specs()) {
            ImGui::PushID(index);
            const std::string inactive = params.inactive_reason(spec.name);
            const bool selected = index == state.selected;
            const std::string label = spec.name + (spec.sweep_values.empty() ? "" : " (knob)");
            // A parameter that changes nothing under the current settings is greyed, with what would enable it.
            if (!inactive.empty()) ImGui::BeginDisabled();
            if (selected) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.3f, 1.0f));
            changed = draw_parameter(params, spec, label) || changed;
            if (selected) ImGui::PopStyleColor();
            if (!inactive.empty()) ImGui::EndDisabled();
            if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
                const std::string tip = spec.help + (spec.same_picture_why.empty() ? "" : "\nmay draw the same picture: " + spec.same_picture_why) +
                                        (inactive.empty() ? "" : "\nno effect now: it " + inactive);
                if (!tip.empty()) ImGui::SetTooltip("%s", tip.c_str());
            }
            if (ImGui::IsItemActivated()) state.selected = index;
            ImGui::PopID();
            ++index;
        }
        return changed;
    }

    // Voreen's visual debugging: every stage with how it ran; choosing one of its images shows it in place of the
    // picture, live. A stage that failed shows its error where it failed.
    static void draw_inspector(PanelState& state) {
        if (state.stages.empty()) return;
        ImGui::Separator();
        if (!ImGui::CollapsingHeader("Inspect (I: next image)", ImGuiTreeNodeFlags_DefaultOpen)) return;
        if (ImGui::Selectable("the picture", state.inspected.empty())) state.inspected.clear();
        for (const auto& stage : state.stages) {
            if (!stage.error.empty()) {
                ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
                ImGui::TextWrapped("%s: %s", stage.name.c_str(), stage.error.c_str());
                ImGui::PopStyleColor();
            } else {
                ImGui::TextDisabled("%s", stage.name.c_str());
            }
            for (const auto& image : stage.images) {
                ImGui::Indent();
                if (ImGui::Selectable(image.c_str(), image == state.inspected)) state.inspected = image;
                ImGui::Unindent();
            }
        }
    }

    static bool draw_parameter(Params& params, const ParamSpec& spec, const std::string& label) {
        switch (spec.type) {
        case ParamType::Float: {
            float v = params.get_float(spec.name);
            if (!ImGui::SliderFloat(label.c_str(), &v, static_cast<float>(spec.min), static_cast<float>(spec.max), "%.4g"))
                return false;
            params.set(spec.name, std::to_string(v));
            return true;
        }
        case ParamType::Int: {
            int v = params.get_int(spec.name);
            if (!ImGui::SliderInt(label.c_str(), &v, static_cast<int>(spec.min), static_cast<int>(spec.max))) return false;
            params.set(spec.name, std::to_string(v));
            return true;
        }
        case ParamType::Bool: {
            bool v = params.get_bool(spec.name);
            if (!ImGui::Checkbox(label.c_str(), &v)) return false;
            params.set(spec.name, v ? "on" : "off");
            return true;
        }
        case ParamType::Choice: {
            const std::string current = params.get_choice(spec.name);
            bool changed = false;
            if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
                for (const auto& choice : spec.choices)
                    if (ImGui::Selectable(choice.c_str(), choice == current)) {
                        params.set(spec.name, choice);
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            return changed;
        }
        case ParamType::File:
        case ParamType::Text: {
            const std::string& file = params.get_file(spec.name);
            ImGui::Text("%s: %s", label.c_str(), file.empty() ? "(none)" : file.c_str());
            return false;
        }
        case ParamType::Vec3: {
            glm::vec3 v = params.get_vec3(spec.name);
            if (!ImGui::SliderFloat3(label.c_str(), &v.x, static_cast<float>(spec.min), static_cast<float>(spec.max), "%.3g"))
                return false;
            params.set(spec.name, std::to_string(v.x) + "," + std::to_string(v.y) + "," + std::to_string(v.z));
            return true;
        }
        }
        return false;
    }

    float ui_scale_ = 1;
};

}  // namespace

int default_panel_width() { return static_cast<int>(kPanelEms * kFontPixels); }

std::unique_ptr<WindowPanel> make_window_panel(GLFWwindow* window, Profile profile, GlVersion version) {
    return std::make_unique<ImGuiPanel>(window, profile, version);
}

}  // namespace gsv
