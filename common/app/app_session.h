#pragma once
// One run of a lab binary: what the modes share (internal to the framework).
#include "common/app/app.h"
#include "common/app/cli.h"
#include "common/gl/framebuffer.h"
#include "common/image/image_compare.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gsv {

struct Session {
    Session() = default;
    ~Session();  // the lab's GL objects go before the context that owns them
    std::unique_ptr<Lab> lab;
    SweepPlanFactory make_sweep_plan;  // the instructor's (reference/), in a solution build; else none: the default plan
    LabInfo info;
    std::string variant;  // "starter" or "solution"
    CliOptions options;
    Params params;
    Params defaults;  // as the lab declared them, before any case or --set
    // The lab's named cases, read from its case file when first asked for (a render the grader runs with --set
    // needs none): see named_cases().
    std::optional<std::vector<RenderCase>> cases;
    std::string lab_dir;               // relative to the kit's root: "solutions/lab02_lic"
    std::filesystem::path executable;  // where the kit's files are looked for beside it
    std::unique_ptr<Assets> assets;
    std::unique_ptr<Context> context;
    std::unique_ptr<LabKit> kit;
    bool told_no_float_target = false;  // frame_target said once that frames render into RGBA8
    bool keep_display = false;          // the EGL display outlives this session's context (render --serve)
    bool told_hidden_window = false;    // headless_backend said once that a hidden window stands in for EGL

    // Creates the context, checks the lab's GL needs, builds the kit and runs lab->setup. A window is
    // `extra_width` wider than --size says (the panel's column beside the picture).
    void open(Backend backend, int extra_width = 0);
    // The backend a headless mode (render, sweep, animate, compare) draws with: --backend's, else EGL, else, where EGL
    // is not compiled in (Windows, macOS), a hidden window, said once on stderr.
    Backend headless_backend();
    // Finds the kit's files (once): the lab's folder, shaders/, data/ and its case file.
    const Assets& find_assets();
    // The cases of the lab's case file, each checked against the declared parameters. Throws gsv::Error naming the
    // file and line of a bad case.
    const std::vector<RenderCase>& named_cases();
    std::filesystem::path case_file();
    // Applies the named case's settings over the current values; throws naming the unknown case and the known ones.
    void apply_case(const std::string& name);
    // Applies the case then the --set assignments, as the command line asked.
    void apply_command_line_settings();
    // Renders one frame into the bound framebuffer: clear, then the lab.
    void render_frame(const Frame& frame);
    // After a parameter change: rebuild shaders if a compile-time parameter moved, tell the lab.
    // Returns a shader error (the last good program keeps running), if any.
    std::optional<std::string> sync_params();
    std::string title() const { return info.id + " (" + variant + ")"; }

private:
    std::vector<ShaderDefine> compiled_defines_;  // what the lab's programs were last built with
};

// A float target read back: the 8-bit image (NaN painted magenta) and how many values were NaN or Inf.
struct Readback {
    Image image;
    FloatStats stats;
    bool non_finite() const { return stats.nan_count > 0 || stats.inf_count > 0; }
};
// The image and, from a float target, its NaN and Inf counts (an RGBA8 target has none to give).
Readback read_back(const Framebuffer& target);
// A frame's target: float, so NaN and Inf survive to the readback instead of silently turning black. An OpenGL ES
// driver without GL_EXT_color_buffer_float cannot draw into float: RGBA8 then, and stderr says once that NaN cannot
// be told from black there.
Framebuffer frame_target(Session& session, int width, int height);

// The image with the lab's legend beside it (--legend). Throws gsv::Error when the lab's colours, with these
// settings, stand for no value.
Image with_lab_legend(Session& session, const Image& image);

// Declares `lab`'s parameters into the session and keeps them as its defaults; `started` gives the rest of where it
// runs from (its folder, variant and executable).
void start_session(Session& session, std::unique_ptr<Lab> lab, const char* lab_dir, const char* variant,
                   const std::filesystem::path& executable);
// Runs `body` as a lab binary's main does: its result, or for what it throws the exit status the lab framework gives
// each kind of error (common/app/exit_status.h), with the error's line on stderr. `stage` names what ran for an
// internal error's line.
int with_exit_status(const Session& session, const std::string& stage, const std::function<int()>& body);

int run_window(Session& session);
int run_render(Session& session);
// render --serve (common/app/app_serve.cpp): the grader's cases one after another over its hand-in socket, each in a
// session, lab and GL context of its own made by `make_lab`, as `started` (the command line's session) runs.
int run_serve(const LabFactory& make_lab, const Session& started);
int run_sweep(Session& session);
// Throws the one-line usage error (exit 2) for a sweep this lab cannot run (no knob, a bad --knob or --values).
void check_sweep_command(const Session& session);
// Throws the one-line usage error (exit 2) for an animate command this lab cannot run, before any GL.
void check_animate_command(const Session& session);
int run_animate(Session& session);
// Renders this binary's image and the reference's (common/app/reference_image.h) and writes the two with their
// difference as one PNG.
int run_compare(Session& session);
// The browser edition's page (common/app/app_web.cpp): opens WebGL 2 on the canvas, sets the lab up and hands the
// session to the page, which draws, sets parameters and reloads shaders through it. Native builds refuse it.
int run_web(std::unique_ptr<Session>& session);  // takes the session only once the page has it

}  // namespace gsv
