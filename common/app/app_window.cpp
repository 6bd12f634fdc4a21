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
#include <memory>
#include <optional>
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

// Opens the window with its panel docked beside the picture (--size is the picture's size, the window is wider) and
// sets the lab's first values.
std::unique_ptr<WindowPanel> open_window(Session& s) {
    s.open(Backend::Window, default_panel_width());
    if (auto error = s.sync_params()) throw Error(*error);
    GLFWwindow* window = s.context->window();
    auto panel = make_window_panel(window, s.kit->profile(), s.context->effective_version());
    if (panel->width() != default_panel_width()) glfwSetWindowSize(window, s.options.width + panel->width(), s.options.height);
    return panel;
}

// "OpenGL ES 3.0 on llvmpipe": the version the kit holds the lab to, which a room comparing profiles reads first.
std::string gl_line(const Session& s) {
    const std::string& renderer = s.context->info().renderer;
    return api_name(s.context->info().profile, s.context->effective_version()) + " on " + renderer.substr(0, renderer.find(" ("));
}

// The window's sizes this frame: the whole framebuffer, and the picture's part of it beside the panel.
struct WindowSize {
    int window_w = 0, window_h = 0, framebuffer_w = 0, framebuffer_h = 0;
    double density = 1;  // framebuffer pixels per window unit
    int width = 0, height = 0;  // the picture's
};

// The window's frames, each in the same steps: input, reloaded shaders, changed values, the lab's picture, what is
// shown in its place, a screenshot, the legend, then the window composed and swapped.
class WindowLoop {
public:
    WindowLoop(Session& s, WindowPanel& panel, std::vector<ScriptedKey> scripted_keys)
        : s_(s), window_(s.context->window()), panel_(panel), scripted_keys_(std::move(scripted_keys)),
          panel_state_{s.params, input_.selected, 0, 0, s.title(), gl_line(s), "", "", {}, "", std::nullopt},
          start_(now_seconds()), last_reload_check_(start_), last_frame_(start_), last_good_(s.params) {
        // Read once, never measured here: a window must not stall (gsv-ceilings measures them, scripts/kit bench runs it).
        ceilings_ = cached_ceilings(s.executable, s.context->info().renderer);
        input_.session = &s;
        input_.panel = &panel;
        input_.panel_state = &panel_state_;
        glfwSetWindowUserPointer(window_, &input_);
        glfwSetKeyCallback(window_, on_key);
        glfwSetMouseButtonCallback(window_, on_mouse_button);
        glfwSetCursorPosCallback(window_, on_cursor);
        glfwSetScrollCallback(window_, on_scroll);
        std::printf("%s", kControls);
        std::fflush(stdout);
    }
    WindowLoop(const WindowLoop&) = delete;
    WindowLoop& operator=(const WindowLoop&) = delete;

    void run() {
        while (!glfwWindowShouldClose(window_)) {
            const double now = take_input();
            reload_shaders(now);
            apply_changed_values();
            const std::optional<WindowSize> size = window_size();
            if (!size) {  // minimised
                glfwWaitEvents();
                continue;
            }
            if (!draw_picture(*size, now)) continue;
            show_in_place();
            const std::string window_shot = take_screenshot();
            refresh_legend();
            compose(*size, window_shot);
            if (finish_frame()) break;
        }
        check_gl_error("the window loop");
    }

private:
    // Events, scripted keys and the animation's step; the time now.
    double take_input() {
        glfwPollEvents();
        press_scripted_keys(window_, scripted_keys_, frame_index_ + 1);
        const double now = now_seconds();
        if (input_.playing) {
            play_animation(s_.params, now - last_frame_);
            input_.params_changed = true;
        }
        last_frame_ = now;
        return now;
    }

    void reload_shaders(double now) {
        if (!input_.reload && now - last_reload_check_ <= 0.25) return;
        last_reload_check_ = now;
        legend_stale_ = true;  // a saved colour function shows in the legend too
        std::optional<std::string> error = input_.reload ? s_.kit->shaders().rebuild_all(param_defines(s_.params))
                                                         : s_.kit->shaders().reload_changed(param_defines(s_.params));
        if (error) {
            // Keep drawing with the last good program; show and print what broke.
            panel_state_.status = *error;
            std::fprintf(stderr, "%s\n", error->c_str());
        } else if (input_.reload) {
            panel_state_.status.clear();
        }
        input_.reload = false;
    }

    // A value the lab refuses (a GL limit, a missing file) must not end a live demo: say why and go back to the last
    // values that drew.
    void refuse(const std::exception& e) {
        panel_state_.status = e.what();
        std::fprintf(stderr, "%s\n", e.what());
        s_.params = last_good_;
        if (auto error = s_.sync_params()) std::fprintf(stderr, "%s\n", error->c_str());
    }

    void apply_changed_values() {
        if (!input_.params_changed) return;
        input_.params_changed = false;
        legend_stale_ = true;
        try {
            if (auto error = s_.sync_params()) {
                panel_state_.status = *error;
                std::fprintf(stderr, "%s\n", error->c_str());
            }
        } catch (const Error& e) {
            refuse(e);
        }
    }

    // None while the window is minimised.
    std::optional<WindowSize> window_size() const {
        WindowSize size;
        glfwGetWindowSize(window_, &size.window_w, &size.window_h);
        glfwGetFramebufferSize(window_, &size.framebuffer_w, &size.framebuffer_h);
        if (size.framebuffer_w == 0 || size.framebuffer_h == 0 || size.window_w == 0) return std::nullopt;
        size.density = static_cast<double>(size.framebuffer_w) / size.window_w;
        const int panel_w = input_.panel_shown ? std::min(size.framebuffer_w - 1, static_cast<int>(std::lround(panel_.width() * size.density)))
                                               : 0;
        size.width = size.framebuffer_w - panel_w;
        size.height = size.framebuffer_h;
        return size;
    }

    // The lab draws into the picture, as headless; false where it refused the values (the last good ones are back).
    bool draw_picture(const WindowSize& size, double now) {
        if (picture_.width() != size.width || picture_.height() != size.height)
            picture_ = Framebuffer(size.width, size.height, ColorFormat::RGBA8);
        picture_.bind();
        const double t0 = now_seconds();
        try {
            s_.render_frame(Frame{size.width, size.height, now - start_, true});
            last_good_ = s_.params;
        } catch (const Error& e) {
            if (frame_index_ == 0) throw;  // the values the lab started with: nothing good to go back to
            refuse(e);
            return false;
        }
        glFinish();
        panel_state_.render_ms = 1000.0 * (now_seconds() - t0);
        // The frame's work is counted again at most each half second: a lab may count it pixel by pixel on the CPU
        // (lab 06 follows each pixel's ray through the box), which every frame of a window would pay for.
        if (ceilings_ && now - bound_at_ >= 0.5) {
            bound_ = roofline(s_.lab->frame_work(Frame{size.width, size.height, now - start_, true}), *ceilings_);
            bound_at_ = now;
        }
        panel_state_.ceiling = bound_ ? bound_->describe(panel_state_.render_ms) : std::string();
        ++frame_index_;
        return true;
    }

    bool screenshot_due() const { return input_.screenshot || frame_index_ == s_.options.screenshot_after; }

    // A stage image, or the reference's view, in place of the picture.
    void show_in_place() {
        panel_state_.stages = s_.lab->inspect_stages();
        if (!panel_state_.inspected.empty()) show_inspected(s_, panel_state_, image_view_, picture_);
        else if (input_.view != PictureView::Yours)
            show_beside_reference(s_, input_.view, panel_state_, live_reference_, image_view_, picture_, screenshot_due());
        else panel_state_.view.clear();
    }

    // A screenshot is the picture as headless draws it, and beside it the window as the room sees it: the window's
    // file, written once the window is composed; empty when none is due.
    std::string take_screenshot() {
        if (!screenshot_due()) return "";
        std::string path = s_.options.out;
        if (path.empty() || screenshot_count_ > 0) path = s_.info.id + "-screenshot-" + std::to_string(screenshot_count_) + ".png";
        write_screenshot(path, picture_.read_rgba8());
        const auto stem = std::filesystem::path(path).replace_extension().string();
        for (const auto& file : s_.lab->write_debug_images(*s_.kit, stem + "-debug")) std::printf("wrote %s\n", file.string().c_str());
        ++screenshot_count_;
        input_.screenshot = false;
        return stem + "-window.png";
    }

    // Before the window's own framebuffer is bound: the legend draws its probe elsewhere.
    void refresh_legend() {
        if (!legend_stale_) return;
        legend_stale_ = false;
        try {
            panel_state_.legend = s_.lab->legend(*s_.kit);
        } catch (const Error& e) {
            panel_state_.legend.reset();
            panel_state_.status = e.what();
        }
    }

    void compose(const WindowSize& size, const std::string& window_shot) {
        Framebuffer::bind_default(size.framebuffer_w, size.framebuffer_h);
        glClearColor(0.06f, 0.06f, 0.07f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, picture_.id());
        glBlitFramebuffer(0, 0, size.width, size.height, 0, 0, size.width, size.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        if (input_.panel_shown || panel_.width() == 0) {  // the title panel takes no room: always drawn
            const float x = static_cast<float>(size.width / size.density);
            if (panel_.draw(panel_state_, PanelPlacement{x, static_cast<float>(size.window_w) - x, static_cast<float>(size.window_h)}))
                input_.params_changed = true;
        }
        if (!window_shot.empty()) {
            glReadBuffer(GL_BACK);
            write_screenshot(window_shot, read_current_framebuffer(size.framebuffer_w, size.framebuffer_h));
        }
    }

    // Swapped and timed; whether --quit-after's frames or seconds are up.
    bool finish_frame() {
        std::fflush(stdout);
        s_.context->swap_buffers();
        clock_.tick();
        panel_state_.frame_ms = clock_.smoothed_ms();
        if (s_.options.quit_after > 0 && frame_index_ >= s_.options.quit_after) return true;
        return s_.options.quit_after_s > 0 && now_seconds() - start_ >= s_.options.quit_after_s;
    }

    Session& s_;
    GLFWwindow* window_;
    WindowPanel& panel_;
    const std::vector<ScriptedKey> scripted_keys_;
    WindowInput input_;
    PanelState panel_state_;  // holds input_.selected: after input_
    ImageView image_view_;
    LiveReference live_reference_;
    FrameClock clock_;
    const double start_;
    double last_reload_check_, last_frame_;
    int frame_index_ = 0;
    int screenshot_count_ = 0;
    bool legend_stale_ = true;  // what the colours stand for: asked again after a change, not every frame
    Params last_good_;
    Framebuffer picture_;  // the lab draws here, as headless, then the picture is copied beside the panel
    std::optional<Ceilings> ceilings_;  // this device's, where measured: the frame line's share of them
    std::optional<Roofline> bound_;     // the last frame's work against them, and when it was counted
    double bound_at_ = -1e9;
};

}  // namespace

int run_window(Session& s) {
    if (s.options.backend && *s.options.backend != Backend::Window)
        throw Error(std::string("window mode draws in a window; --backend ") + backend_name(*s.options.backend) +
                    " is for render and sweep");
    std::vector<ScriptedKey> scripted_keys = parse_scripted_keys(s.options.presses);
    const std::unique_ptr<WindowPanel> panel = open_window(s);
    WindowLoop(s, *panel, std::move(scripted_keys)).run();
    return kExitOk;
}

}  // namespace gsv
