// Web mode: the browser edition's page. The same lab, parameters, cases and shader library as the window, on WebGL 2
// (the es profile at the lab's lowest ES version); HTML is its panel. main() sets the lab up and returns; the page
// then calls in through embind (common/app/app_web.h) to set parameters, draw frames and reload edited shaders, the
// way the window's loop does with keys and saved files.
#include "common/app/app_web.h"

#include "common/app/app_session.h"
#include "common/app/page_description.h"
#include "common/app/live_controls.h"
#include "common/core/error.h"
#include "common/shader/param_uniforms.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/timing/timing.h"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#include <emscripten/bind.h>
#include <emscripten/html5.h>
#endif

#include <cstdio>
#include <new>
#include <string>

namespace gsv {

#ifndef __EMSCRIPTEN__

int run_web(std::unique_ptr<Session>&) {
    throw Error("web mode is the browser edition's: scripts/kit web builds each lab's page, scripts/kit serve serves them");
}

#else

int run_window(Session&) { throw Error("the browser edition has no window mode: the page is its window"); }
int run_compare(Session&) { throw Error("the browser edition compares in the page (its self-check)"); }

namespace {

struct WebPage {
    std::unique_ptr<Session> session;
    Framebuffer picture;  // the lab draws here, as in the window, then the picture is copied to the canvas
    Params last_good;     // the last values that drew: a refused value goes back to them
    std::string status;   // the last error, one line, for the page
    double start = 0;
    bool draw_again = false;  // the last frame did part of its work (LabKit::ask_for_another_frame)
    double last_frame_ms = -1;  // the last timed frame's time (web_draw), -1 before the first
    double last_timed = -1e9;   // when it was timed, in now_seconds()
};

WebPage* page = nullptr;

WebPage& the_page() {
    if (!page) throw Error("the lab has not started (see the line above the picture)");
    return *page;
}

// Runs `what`, turning an error into its one line (and the page's status) instead of a JavaScript exception.
template <class F>
std::string guarded(F&& what) {
    try {
        what();
        return "";
    } catch (const std::exception& e) {
        if (page) page->status = e.what();
        return e.what();
    }
}

// The page's memory (WebAssembly's, at most 2 GiB) cannot hold what the values ask for: a refusal like a GL limit's,
// naming the values that differ from the last ones that drew; the page goes back to those.
std::string out_of_memory(WebPage& p) {
    std::string asked;
    const Params& now = p.session->params;
    for (std::size_t i = 0; i < now.specs().size(); ++i)
        if (now.text_at(i) != p.last_good.text_at(i))
            asked += (asked.empty() ? "" : " ") + now.specs()[i].qualified_name() + "=" + now.text_at(i);
    p.session->params = p.last_good;
    if (auto error = p.session->sync_params()) std::fprintf(stderr, "%s\n", error->c_str());
    return (asked.empty() ? std::string("these values") : asked) +
           ": more memory than the page can hold (WebAssembly's); the last values that drew are back (the desktop build "
           "holds more)";
}

// A value the lab refuses (a GL limit, a missing file) must not end the page: say why and go back to the last values
// that drew, as the window does.
void sync_or_refuse(WebPage& p) {
    try {
        if (auto error = p.session->sync_params()) p.status = *error;
    } catch (const Error&) {
        p.session->params = p.last_good;
        if (auto error = p.session->sync_params()) std::fprintf(stderr, "%s\n", error->c_str());
        throw;
    } catch (const std::bad_alloc&) {
        throw Error(out_of_memory(p));
    }
}

}  // namespace

int run_web(std::unique_ptr<Session>& owned) {
    Session& s = *owned;
    s.options.profile = Profile::Es;  // WebGL 2 is OpenGL ES 3.0
    s.open(Backend::Web);
    if (auto error = s.sync_params()) throw Error(*error);
    page = new WebPage{std::move(owned), Framebuffer(), s.params, "", now_seconds()};
    return kExitOk;
}

Session& web_session() { return *the_page().session; }

std::string web_describe() {
    WebPage& p = the_page();
    Session& s = *p.session;
    const ContextInfo& gl = s.context->info();
    Json out = Json::object();
    out["lab"] = s.info.id;
    out["title"] = s.info.title;
    out["variant"] = s.variant;
    out["root"] = s.assets->root().string();
    out["lab_dir"] = s.lab_dir;
    out["width"] = s.options.width;
    out["height"] = s.options.height;
    out["gl"] = api_name(Profile::Es, s.context->effective_version()) + " on " + gl.renderer;
    out["gl_version"] = gl.version_string;
    out["float_target"] = Framebuffer::float_renderable();
    out["params"] = describe_params(s.params);
    out["cases"] = describe_cases(s.named_cases());
    return out.dump(0);
}

std::string web_states() { return param_states(the_page().session->params).dump(0); }

std::string web_set_param(const std::string& name, const std::string& value) {
    return guarded([&] {
        WebPage& p = the_page();
        p.session->params.set(name, value);
        sync_or_refuse(p);
    });
}

std::string web_apply_case(const std::string& name) {
    return guarded([&] {
        WebPage& p = the_page();
        // A case is its settings over the defaults, not over the values before it (the window's C).
        p.session->params = p.session->defaults;
        if (!name.empty()) p.session->apply_case(name);
        sync_or_refuse(p);
    });
}

std::string web_play(double seconds) {
    return guarded([&] {
        WebPage& p = the_page();
        play_animation(p.session->params, seconds);
        sync_or_refuse(p);
    });
}

// A mouse drag on the canvas, or a scroll, as in the window.
std::string web_orbit(double dx, double dy, double zoom_steps) {
    return guarded([&] {
        WebPage& p = the_page();
        if (dx != 0 || dy != 0) orbit_drag(p.session->params, dx, dy);
        if (zoom_steps != 0) orbit_zoom(p.session->params, zoom_steps);
        sync_or_refuse(p);
    });
}

// Every program rebuilt from the files as they are now (the editor writes them): the window's R, and what its hot
// reload does on a save. A failed build keeps the last good program; the error names the student's file and line.
std::string web_reload_shaders() {
    return guarded([&] {
        Session& s = *the_page().session;
        if (auto error = s.kit->shaders().rebuild_all(param_defines(s.params))) throw Error(*error);
    });
}

// WebGL's finish() returns before Chromium's GPU process has run the commands (measured: LIC's 148 ms frame read as
// 0.3 ms); reading a pixel of the target back into the page's memory waits for the drawing into it. A read-back of
// another framebuffer does not: llvmpipe left the target's drawing queued (LIC's frames read 0.4 ms for 7.4 natively).
// A float target is read as floats, the only way WebGL 2 reads it.
static void wait_for_gpu(const Framebuffer& target) {
    glFinish();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target.id());
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    if (target.format() == ColorFormat::RGBA8) {
        unsigned char pixel[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    } else {
        float pixel[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, pixel);
    }
}

// One frame into the picture, copied onto the canvas. Returns the time of the last frame timed, in milliseconds;
// negative when the frame failed (status). A frame is timed, bracketed by waits for the GPU (wait_for_gpu), at most
// every kTimedEvery seconds: a wait is a read-back that stalls the browser's GPU process (about 2 ms on llvmpipe), and
// bracketing every frame of a drag or an animation with two of them slowed the page's frames to half their speed.
double web_draw() {
    if (!page) return -1;
    WebPage& p = *page;
    Session& s = *p.session;
    const int width = s.options.width, height = s.options.height;
    if (p.picture.width() != width || p.picture.height() != height) p.picture = Framebuffer(width, height, ColorFormat::RGBA8);
    try {
        constexpr double kTimedEvery = 0.5;
        p.picture.bind();
        const bool timed = now_seconds() - p.last_timed >= kTimedEvery;
        if (timed) wait_for_gpu(p.picture);
        const double t0 = now_seconds();
        s.render_frame(Frame{width, height, t0 - p.start, true});
        p.draw_again = s.kit->take_another_frame_request();
        if (timed) {
            wait_for_gpu(p.picture);
            p.last_frame_ms = 1000.0 * (now_seconds() - t0);
            p.last_timed = t0;
        }
        check_gl_error("drawing the frame");
        p.last_good = s.params;
        Framebuffer::bind_default(width, height);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, p.picture.id());
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return p.last_frame_ms;
    } catch (const std::bad_alloc&) {
        p.status = out_of_memory(p);
        return -1;
    } catch (const std::exception& e) {
        p.status = e.what();
        s.params = p.last_good;
        guarded([&] { sync_or_refuse(p); });
        return -1;
    }
}

// The picture at another size: the page's full-screen view draws at the screen's size, and back at the lab's on
// leaving it. The lab draws at the frame's size, as in a resized window; the canvas's drawing buffer follows.
std::string web_resize(int width, int height) {
    return guarded([&] {
        Session& s = *the_page().session;
        constexpr int kLargest = 8192;
        if (width < 16 || height < 16 || width > kLargest || height > kLargest)
            throw Error("a picture of " + std::to_string(width) + "x" + std::to_string(height) + " is outside 16x16 to " +
                        std::to_string(kLargest) + "x" + std::to_string(kLargest));
        s.options.width = width;
        s.options.height = height;
        emscripten_set_canvas_element_size("#canvas", width, height);
    });
}

// The benchmark's frames (scripts/bench_web.js): `count` frames as render mode draws them (not interactive: lab 05 runs
// its steps from the start each frame; into the float target where the browser has one), after one untimed frame, and
// bracketed once by waits for the GPU, so the read-back's fixed cost is shared by them rather than paid by each.
// Returns milliseconds per frame; negative on failure (status).
double web_time_frames(int count) {
    if (!page || count < 1) return -1;
    WebPage& p = *page;
    Session& s = *p.session;
    const int width = s.options.width, height = s.options.height;
    try {
        Framebuffer target = frame_target(s, width, height);
        target.bind();
        s.render_frame(Frame{width, height, 0.0});
        wait_for_gpu(target);
        const double t0 = now_seconds();
        for (int i = 0; i < count; ++i) s.render_frame(Frame{width, height, 0.0});
        wait_for_gpu(target);
        const double ms = 1000.0 * (now_seconds() - t0) / count;
        check_gl_error("timing frames");
        return ms;
    } catch (const std::exception& e) {
        p.status = e.what();
        return -1;
    }
}

std::string web_status() { return page ? page->status : ""; }

bool web_draw_again() { return page && page->draw_again; }

// While the picture is behind its values (web_draw_again), how far it has got, in the lab's words; else empty.
std::string web_progress() { return page && page->draw_again ? page->session->kit->progress() : ""; }

EMSCRIPTEN_BINDINGS(gsv_web_page) {
    emscripten::function("describe", &web_describe);
    emscripten::function("states", &web_states);
    emscripten::function("setParam", &web_set_param);
    emscripten::function("applyCase", &web_apply_case);
    emscripten::function("play", &web_play);
    emscripten::function("orbit", &web_orbit);
    emscripten::function("reloadShaders", &web_reload_shaders);
    emscripten::function("draw", &web_draw);
    emscripten::function("status", &web_status);
    emscripten::function("resize", &web_resize);
    emscripten::function("drawAgain", &web_draw_again);
    emscripten::function("progress", &web_progress);
    emscripten::function("timeFrames", &web_time_frames);
}

#endif

}  // namespace gsv
