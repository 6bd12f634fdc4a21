// Window mode: the lab live, every parameter on keys (and sliders with ImGui), frame time on screen,
// hot reload of shader files, screenshots, and the command line that reproduces what is on screen.
#include "common/app/app_session.h"
#include "common/app/live_controls.h"
#include "common/shader/param_uniforms.h"
#include "common/app/window_reference.h"
#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/image/image.h"
#include "common/timing/timing.h"
#include "common/window/image_view.h"
#include "common/window/scripted_keys.h"
#include "common/window/window_panel.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>

namespace gsv {
namespace {

const char* kControls =
    "keys: Tab/Down next parameter, Shift+Tab/Up previous, Left/Right change it (Shift: x10),\n"
    "      C next case, D defaults, R reload shaders, S screenshot, P print the command line, H help, Esc quit,\n"
    "      Space play/pause the animated parameter (labs that have one), U hide/show the panel,\n"
    "      I show the next stage image (visual debugging: lab 06's ports),\n"
    "      V yours / the reference / split / the difference (the reference: the kit's solution, or the golden image)\n"
    "mouse: drag to orbit, scroll to zoom (3D labs)\n";

struct WindowInput {
    Session* session = nullptr;
    WindowPanel* panel = nullptr;
    PanelState* panel_state = nullptr;
    int selected = 0;
    int case_index = -1;
    bool params_changed = false;
    bool playing = false;  // off at start, so a window screenshot is the same picture every run
    bool screenshot = false;
    bool reload = false;
    bool panel_shown = true;
    PictureView view = PictureView::Yours;
    bool dragging = false;
    double last_x = 0, last_y = 0;
};

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

const char* view_name(PictureView view) {
    switch (view) {
    case PictureView::Yours: return "yours";
    case PictureView::Reference: return "the reference";
    case PictureView::Split: return "yours | the reference";
    case PictureView::Difference: return "the difference";
    }
    return "";
}

// The picture, then every stage image in turn, then the picture again.
void inspect_next(PanelState& state) {
    std::vector<std::string> images{""};
    for (const auto& stage : state.stages) images.insert(images.end(), stage.images.begin(), stage.images.end());
    if (images.size() == 1) {
        std::printf("this lab has no stages to inspect\n");
        return;
    }
    const auto at = std::find(images.begin(), images.end(), state.inspected);
    state.inspected = at == images.end() || at + 1 == images.end() ? images.front() : *(at + 1);
    std::printf("inspecting %s\n", state.inspected.empty() ? "the picture" : state.inspected.c_str());
}

void on_key(GLFWwindow* window, int key, int, int action, int mods) {
    auto* in = static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
    if (action == GLFW_RELEASE || (in->panel_shown && in->panel && in->panel->wants_keyboard())) return;
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
    case GLFW_KEY_LEFT: {
        params.nudge(name, (key == GLFW_KEY_RIGHT ? 1 : -1) * (shift ? 10 : 1));
        in->params_changed = true;
        const std::string inactive = params.inactive_reason(name);
        std::printf("%s = %s%s%s\n", name.c_str(), params.get_text(name).c_str(),
                    inactive.empty() ? "" : " (no effect now: it ", inactive.empty() ? "" : (inactive + ")").c_str());
        break;
    }
    case GLFW_KEY_U: in->panel_shown = !in->panel_shown; break;
    case GLFW_KEY_I: inspect_next(*in->panel_state); break;
    case GLFW_KEY_V:
        in->view = next_view(in->view);
        std::printf("view: %s\n", view_name(in->view));
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
            // What the window shows is now this case: the reference (a solution's render, or this case's golden) too.
            s.options.case_name = next.name;
            s.options.assignments.clear();
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
    in->dragging = action == GLFW_PRESS && !(in->panel_shown && in->panel && in->panel->wants_mouse());
    glfwGetCursorPos(window, &in->last_x, &in->last_y);
}

void on_cursor(GLFWwindow* window, double x, double y) {
    auto* in = static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
    if (!in->dragging) return;
    if (orbit_drag(in->session->params, x - in->last_x, y - in->last_y)) in->params_changed = true;
    in->last_x = x;
    in->last_y = y;
}

void on_scroll(GLFWwindow* window, double, double dy) {
    auto* in = static_cast<WindowInput*>(glfwGetWindowUserPointer(window));
    if (in->panel_shown && in->panel && in->panel->wants_mouse()) return;
    if (orbit_zoom(in->session->params, dy)) in->params_changed = true;
}

// Scripted key presses (--press KEY@FRAME) go through the same handler as the keyboard's.
void press_scripted_keys(GLFWwindow* window, const std::vector<ScriptedKey>& keys, int next_frame) {
    for (const auto& k : keys)
        if (k.frame == next_frame) on_key(window, k.key, 0, GLFW_PRESS, 0);
}

// A stage image in place of the picture, read back each frame; where its stage has none now (it failed), the
// picture stays and the status says why.
void show_inspected(Session& s, PanelState& state, ImageView& view, const Framebuffer& picture) {
    const std::optional<Image> image = s.lab->inspect_image(*s.kit, state.inspected);
    if (!image) {
        std::string why = "no image now";
        for (const auto& stage : state.stages)
            if (state.inspected.rfind(stage.name + ".", 0) == 0 && !stage.error.empty()) why = stage.name + ": " + stage.error;
        state.status = state.inspected + ": " + why;
        return;
    }
    picture.bind();
    view.draw(*image, picture.width(), picture.height());
}

// The reference's view of the picture: the solution renders these settings in a child process while the window
// goes on drawing yours; a screenshot waits for it, so that it shows what it says.
void show_beside_reference(Session& s, PictureView view, PanelState& state, LiveReference& live, ImageView& image_view,
                           const Framebuffer& picture, bool screenshot) {
    const Image* reference = live.get(s, picture.width(), picture.height());
    for (int waited = 0; !reference && screenshot && live.pending() && waited < 1200; ++waited) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        reference = live.get(s, picture.width(), picture.height());
    }
    if (!reference) {
        state.view = std::string(view_name(view)) + ": " + live.status();
        return;
    }
    const ComposedView composed = compose_view(view, picture.read_rgba8(), *reference, live.status());
    if (state.view != composed.caption) std::printf("view: %s\n", composed.caption.c_str());
    state.view = composed.caption;
    picture.bind();
    image_view.draw(composed.image, picture.width(), picture.height());
}

void write_screenshot(const std::string& path, const Image& image) {
    write_png(path, image);
    std::printf("wrote %s\n", path.c_str());
}

}  // namespace

int run_window(Session& s) {
    if (s.options.backend && *s.options.backend != Backend::Window)
        throw Error(std::string("window mode draws in a window; --backend ") + backend_name(*s.options.backend) +
                    " is for render and sweep");
    const std::vector<ScriptedKey> scripted_keys = parse_scripted_keys(s.options.presses);
    // The panel docks in a column beside the picture: --size is the picture's size, the window is wider.
    s.open(Backend::Window, default_panel_width());
    if (auto error = s.sync_params()) throw Error(*error);
    GLFWwindow* window = s.context->window();
    auto panel = make_window_panel(window, s.kit->profile(), s.context->effective_version());
    if (panel->width() != default_panel_width()) glfwSetWindowSize(window, s.options.width + panel->width(), s.options.height);

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

    // "OpenGL ES 3.0 on llvmpipe": the version the kit holds the lab to, which a room comparing profiles reads first.
    const std::string& renderer = s.context->info().renderer;
    const std::string gl_line = api_name(s.context->info().profile, s.context->effective_version()) + " on " +
                                renderer.substr(0, renderer.find(" ("));
    PanelState panel_state{s.params, input.selected, 0, 0, s.title(), gl_line, "", "", {}, "", std::nullopt};
    input.panel_state = &panel_state;
    ImageView image_view;
    LiveReference live_reference;
    FrameClock clock;
    const double start = now_seconds();
    double last_reload_check = start;
    double last_frame = start;
    int frame_index = 0;
    int screenshot_count = 0;
    bool legend_stale = true;  // what the colours stand for: asked again after a change, not every frame
    Params last_good = s.params;
    Framebuffer picture;  // the lab draws here, as headless, then the picture is copied beside the panel
    while (!glfwWindowShouldClose(window)) {
        glfwPollEvents();
        press_scripted_keys(window, scripted_keys, frame_index + 1);
        const double now = now_seconds();
        if (input.playing) {
            play_animation(s.params, now - last_frame);
            input.params_changed = true;
        }
        last_frame = now;
        if (input.reload || now - last_reload_check > 0.25) {
            last_reload_check = now;
            legend_stale = true;  // a saved colour function shows in the legend too
            std::optional<std::string> error = input.reload ? s.kit->shaders().rebuild_all(param_defines(s.params))
                                                            : s.kit->shaders().reload_changed(param_defines(s.params));
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

        int window_w = 0, window_h = 0, framebuffer_w = 0, framebuffer_h = 0;
        glfwGetWindowSize(window, &window_w, &window_h);
        glfwGetFramebufferSize(window, &framebuffer_w, &framebuffer_h);
        if (framebuffer_w == 0 || framebuffer_h == 0 || window_w == 0) {  // minimised
            glfwWaitEvents();
            continue;
        }
        const double density = static_cast<double>(framebuffer_w) / window_w;
        const int panel_w = input.panel_shown ? std::min(framebuffer_w - 1, static_cast<int>(std::lround(panel->width() * density))) : 0;
        const int width = framebuffer_w - panel_w, height = framebuffer_h;
        if (picture.width() != width || picture.height() != height) picture = Framebuffer(width, height, ColorFormat::RGBA8);
        picture.bind();
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
        panel_state.stages = s.lab->inspect_stages();
        if (!panel_state.inspected.empty()) show_inspected(s, panel_state, image_view, picture);
        else if (input.view != PictureView::Yours)
            show_beside_reference(s, input.view, panel_state, live_reference, image_view, picture,
                                  input.screenshot || frame_index == s.options.screenshot_after);
        else panel_state.view.clear();

        // A screenshot is the picture as headless draws it, and beside it the window as the room sees it.
        std::string window_shot;
        if (input.screenshot || frame_index == s.options.screenshot_after) {
            std::string path = s.options.out;
            if (path.empty() || screenshot_count > 0)
                path = s.info.id + "-screenshot-" + std::to_string(screenshot_count) + ".png";
            write_screenshot(path, picture.read_rgba8());
            const auto stem = std::filesystem::path(path).replace_extension().string();
            for (const auto& file : s.lab->write_debug_images(*s.kit, stem + "-debug")) std::printf("wrote %s\n", file.string().c_str());
            window_shot = stem + "-window.png";
            ++screenshot_count;
            input.screenshot = false;
        }
        if (legend_stale) {  // before the window's own framebuffer is bound: the legend draws its probe elsewhere
            legend_stale = false;
            try {
                panel_state.legend = s.lab->legend(*s.kit);
            } catch (const Error& e) {
                panel_state.legend.reset();
                panel_state.status = e.what();
            }
        }
        Framebuffer::bind_default(framebuffer_w, framebuffer_h);
        glClearColor(0.06f, 0.06f, 0.07f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, picture.id());
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        if (input.panel_shown || panel->width() == 0) {  // the title panel takes no room: always drawn
            const float x = static_cast<float>(width / density);
            if (panel->draw(panel_state, PanelPlacement{x, static_cast<float>(window_w) - x, static_cast<float>(window_h)}))
                input.params_changed = true;
        }
        if (!window_shot.empty()) {
            glReadBuffer(GL_BACK);
            write_screenshot(window_shot, read_current_framebuffer(framebuffer_w, framebuffer_h));
        }
        std::fflush(stdout);
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
