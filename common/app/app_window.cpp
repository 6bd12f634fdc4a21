// Window mode: the lab live, every parameter on keys (and sliders with ImGui), frame time on screen,
// hot reload of shader files, screenshots, and the command line that reproduces what is on screen.
#include "common/app/app_session.h"
#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/image/image.h"
#include "common/timing/timing.h"
#include "common/window/window_panel.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace gsv {
namespace {

const char* kControls =
    "keys: Tab/Down next parameter, Shift+Tab/Up previous, Left/Right change it (Shift: x10),\n"
    "      C next case, D defaults, R reload shaders, S screenshot, P print the command line, H help, Esc quit,\n"
    "      Space play/pause the animated parameter (labs that have one)\n"
    "mouse: drag to orbit, scroll to zoom (3D labs)\n";

struct WindowInput {
    Session* session = nullptr;
    WindowPanel* panel = nullptr;
    int selected = 0;
    int case_index = -1;
    bool params_changed = false;
    bool playing = false;  // off at start, so a window screenshot is the same picture every run
    bool screenshot = false;
    bool reload = false;
    bool dragging = false;
    double last_x = 0, last_y = 0;
};

bool has_param(const Params& params, const std::string& name) {
    for (const auto& s : params.specs())
        if (s.name == name) return true;
    return false;
}

void adjust(Params& params, const std::string& name, double delta) {
    const ParamSpec& s = params.spec(name);
    params.set(name, std::to_string(std::clamp(params.get_float(name) + delta, s.min, s.max)));
}

// Wall time, not frames, drives playback: one sweep of the range takes 8 s on llvmpipe and on a GPU alike.
void play(Params& params, double seconds) {
    const ParamSpec* axis = params.animation_axis();
    if (!axis || !(axis->max > axis->min)) return;
    const double span = axis->max - axis->min;
    double v = params.get_float(axis->name) + span / 8 * seconds;
    if (v > axis->max) v = axis->min + std::fmod(v - axis->min, span);
    params.set(axis->name, format_number(std::clamp(v, axis->min, axis->max), 9));
}

void toggle_play(WindowInput& in) {
    const ParamSpec* axis = in.session->params.animation_axis();
    if (!axis) {
        std::printf("%s has no animated parameter to play\n", in.session->info.id.c_str());
        return;
    }
    in.playing = !in.playing;
    std::printf("%s %s = %s\n", in.playing ? "playing" : "paused", axis->name.c_str(),
                in.session->params.get_text(axis->name).c_str());
}

std::string command_line(const Session& s) {
    std::string line = s.info.id + (s.variant == "solution" ? "_solution" : "") + " render";
    for (const auto& spec : s.params.specs()) {
        const std::string value = s.params.get_text(spec.name);
        if (value != s.defaults.get_text(spec.name)) line += " --set " + spec.name + "=" + value;
    }
    return line;
}

void on_key(GLFWwindow* window, int key, int, int action, int mods) {
    auto* in = static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
    if (action == GLFW_RELEASE || (in->panel && in->panel->wants_keyboard())) return;
    Session& s = *in->session;
    Params& params = s.params;
    const int count = static_cast<int>(params.specs().size());
    const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
    const std::string& name = params.specs()[static_cast<std::size_t>(in->selected)].name;
    switch (key) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
    case GLFW_KEY_H: std::printf("%s%s", kControls, params.describe().c_str()); break;
    case GLFW_KEY_TAB: in->selected = (in->selected + (shift ? count - 1 : 1)) % count; break;
    case GLFW_KEY_DOWN: in->selected = (in->selected + 1) % count; break;
    case GLFW_KEY_UP: in->selected = (in->selected + count - 1) % count; break;
    case GLFW_KEY_RIGHT:
    case GLFW_KEY_LEFT:
        params.nudge(name, (key == GLFW_KEY_RIGHT ? 1 : -1) * (shift ? 10 : 1));
        in->params_changed = true;
        std::printf("%s = %s\n", name.c_str(), params.get_text(name).c_str());
        break;
    case GLFW_KEY_C:
        try {
            const std::vector<RenderCase>& cases = s.named_cases();
            if (cases.empty()) break;
            in->case_index = (in->case_index + 1) % static_cast<int>(cases.size());
            const RenderCase& next = cases[static_cast<std::size_t>(in->case_index)];
            // A case is its settings over the defaults, not over the case before it.
            params = s.defaults;
            s.apply_case(next.name);
            in->params_changed = true;
            std::printf("case %s: %s\n", next.name.c_str(), next.description.c_str());
        } catch (const Error& e) {
            std::fprintf(stderr, "%s: %s\n", s.info.id.c_str(), e.what());
        }
        break;
    case GLFW_KEY_D:
        params = s.defaults;
        in->params_changed = true;
        break;
    case GLFW_KEY_R: in->reload = true; break;
    case GLFW_KEY_S: in->screenshot = true; break;
    case GLFW_KEY_P: std::printf("%s\n", command_line(s).c_str()); break;
    case GLFW_KEY_SPACE:
        if (action == GLFW_PRESS) toggle_play(*in);  // held down, it would flicker between play and pause
        break;
    default: break;
    }
    std::fflush(stdout);
}

void on_mouse_button(GLFWwindow* window, int button, int action, int) {
    auto* in = static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    in->dragging = action == GLFW_PRESS && !(in->panel && in->panel->wants_mouse());
    glfwGetCursorPos(window, &in->last_x, &in->last_y);
}

void on_cursor(GLFWwindow* window, double x, double y) {
    auto* in = static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
    if (!in->dragging) return;
    Params& params = in->session->params;
    if (has_param(params, "camera_yaw")) {
        adjust(params, "camera_yaw", -0.4 * (x - in->last_x));
        adjust(params, "camera_pitch", 0.4 * (y - in->last_y));
        in->params_changed = true;
    }
    in->last_x = x;
    in->last_y = y;
}

void on_scroll(GLFWwindow* window, double, double dy) {
    auto* in = static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
    if (in->panel && in->panel->wants_mouse()) return;
    Params& params = in->session->params;
    if (has_param(params, "camera_distance")) {
        adjust(params, "camera_distance", -0.2 * dy);
        in->params_changed = true;
    }
}

}  // namespace

int run_window(Session& s) {
    if (s.options.backend && *s.options.backend != Backend::Window)
        throw Error(std::string("window mode draws in a window; --backend ") + backend_name(*s.options.backend) +
                    " is for render and sweep");
    s.open(Backend::Window);
    if (auto error = s.sync_params()) throw Error(*error);
    GLFWwindow* window = s.context->window();
    auto panel = make_window_panel(window, s.context->effective_version());

    WindowInput input;
    input.session = &s;
    input.panel = panel.get();
    glfwSetWindowUserPointer(window, &input);
    glfwSetKeyCallback(window, on_key);
    glfwSetMouseButtonCallback(window, on_mouse_button);
    glfwSetCursorPosCallback(window, on_cursor);
    glfwSetScrollCallback(window, on_scroll);
    std::printf("%s", kControls);
    std::fflush(stdout);

    PanelState panel_state{s.params, input.selected, 0, 0, s.title(), s.context->describe(), "", std::nullopt};
    FrameClock clock;
    const double start = now_seconds();
    double last_reload_check = start;
    double last_frame = start;
    int frame_index = 0;
    int screenshot_count = 0;
    bool legend_stale = true;  // what the colours stand for: asked again after a change, not every frame
    Params last_good = s.params;
    while (!glfwWindowShouldClose(window)) {
        glfwPollEvents();
        const double now = now_seconds();
        if (input.playing) {
            play(s.params, now - last_frame);
            input.params_changed = true;
        }
        last_frame = now;
        if (input.reload || now - last_reload_check > 0.25) {
            last_reload_check = now;
            legend_stale = true;  // a saved colour function shows in the legend too
            std::optional<std::string> error = input.reload ? s.kit->shaders().rebuild_all(s.params.defines())
                                                            : s.kit->shaders().reload_changed(s.params.defines());
            if (error) {
                // Keep drawing with the last good program; show and print what broke.
                panel_state.status = *error;
                std::fprintf(stderr, "%s\n", error->c_str());
            } else if (input.reload) {
                panel_state.status.clear();
            }
            input.reload = false;
        }
        // A value the lab refuses (a GL limit, a missing file) must not end a live demo: say why and go back
        // to the last values that drew.
        auto refuse = [&](const std::exception& e) {
            panel_state.status = e.what();
            std::fprintf(stderr, "%s\n", e.what());
            s.params = last_good;
            if (auto error = s.sync_params()) std::fprintf(stderr, "%s\n", error->c_str());
        };
        if (input.params_changed) {
            input.params_changed = false;
            legend_stale = true;
            try {
                if (auto error = s.sync_params()) {
                    panel_state.status = *error;
                    std::fprintf(stderr, "%s\n", error->c_str());
                }
            } catch (const Error& e) {
                refuse(e);
            }
        }

        int width = 0, height = 0;
        glfwGetFramebufferSize(window, &width, &height);
        if (width == 0 || height == 0) {  // minimised
            glfwWaitEvents();
            continue;
        }
        Framebuffer::bind_default(width, height);
        const double t0 = now_seconds();
        try {
            s.render_frame(Frame{width, height, now - start, true});
            last_good = s.params;
        } catch (const Error& e) {
            if (frame_index == 0) throw;  // the values the lab started with: nothing good to go back to
            refuse(e);
            continue;
        }
        glFinish();
        panel_state.render_ms = 1000.0 * (now_seconds() - t0);
        ++frame_index;

        if (input.screenshot || frame_index == s.options.screenshot_after) {
            glReadBuffer(GL_BACK);
            const Image shot = read_current_framebuffer(width, height);
            std::string path = s.options.out;
            if (path.empty() || screenshot_count > 0)
                path = s.info.id + "-screenshot-" + std::to_string(screenshot_count) + ".png";
            write_png(path, shot);
            std::printf("wrote %s\n", path.c_str());
            const auto debug = std::filesystem::path(path).replace_extension().string() + "-debug";
            for (const auto& file : s.lab->write_debug_images(*s.kit, debug)) std::printf("wrote %s\n", file.string().c_str());
            Framebuffer::bind_default(width, height);  // the debug images bound their own targets
            std::fflush(stdout);
            ++screenshot_count;
            input.screenshot = false;
        }
        if (legend_stale) {
            legend_stale = false;
            try {
                panel_state.legend = s.lab->legend(*s.kit);
            } catch (const Error& e) {
                panel_state.legend.reset();
                panel_state.status = e.what();
            }
        }
        if (panel->draw(panel_state)) input.params_changed = true;
        s.context->swap_buffers();
        clock.tick();
        panel_state.frame_ms = clock.smoothed_ms();
        if (s.options.quit_after > 0 && frame_index >= s.options.quit_after) break;
        if (s.options.quit_after_s > 0 && now_seconds() - start >= s.options.quit_after_s) break;
    }
    check_gl_error("the window loop");
    return kExitOk;
}

}  // namespace gsv
