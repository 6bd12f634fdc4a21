#include "common/app/app.h"

#include "common/app/app_session.h"
#include "common/app/fetch_counter.h"
#include "common/core/error.h"
#include "common/core/version.h"
#include "common/gl/gl.h"
#include "common/shader/param_uniforms.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace gsv {

std::optional<ShaderDefine> texel_snap_define() {
    const char* value = std::getenv("GSV_TEXEL_SNAP");
    if (!value || !*value) return std::nullopt;
    const std::string text = value;
    char* end = nullptr;
    const long steps = std::strtol(text.c_str(), &end, 10);
    if (*end != '\0' || steps < 2 || steps > 65536)
        throw Error("GSV_TEXEL_SNAP=" + text + ": the steps per texel texture coordinates are snapped to, a whole number "
                    "2..65536 (256: GPUs' 8-bit filter weights); unset it for unsnapped lookups");
    return ShaderDefine{"GSV_TEXEL_SNAP", std::to_string(steps)};
}

LabKit::LabKit(Context& context, Params& params, const Assets& assets, Profile profile)
    : context_(context), params_(params), assets_(assets), profile_(profile),
      shaders_([&] {
          PreprocessOptions options;
          options.profile = profile;
          options.version = context.effective_version();
          options.include_dirs = assets.shader_include_dirs();
          if (const auto snap = texel_snap_define()) options.defines.push_back(*snap);
          if (const auto count = fetch_count_define()) options.defines.push_back(*count);
          return options;
      }()) {}

void LabKit::require(const GlFeature& feature, const std::string& asked_by) const {
    if (!allows(feature))
        throw UnsupportedError(asked_by + " " + missing_feature_message(feature, profile_, gl_version()));
}

const ShaderLibrary::Entry& LabKit::program(const std::string& name, const std::vector<std::string>& files,
                                            const std::vector<std::string>& captured) {
    ProgramSpec spec;
    spec.name = name;
    spec.captured = captured;
    for (const auto& f : files) spec.files.push_back(assets_.shader_file(f));
    const ShaderLibrary::Entry& entry = shaders_.add(std::move(spec), param_defines(params_));
    check_param_uniforms(params_, entry.program().active_uniform_kinds(), name);
    return entry;
}

std::vector<ShaderDefine> LabKit::defines() const { return param_defines(params_); }

const ShaderProgram& LabKit::use(const ShaderLibrary::Entry& entry) const {
    const ShaderProgram& program = entry.program();
    program.use();
    apply_param_uniforms(params_, program);
    return program;
}

void add_orbit_camera(Params& params, float yaw, float pitch, float distance, float min_distance) {
    params.add_float("camera_yaw", yaw, -360, 360, "camera azimuth in degrees (drag the mouse)").with_step(5);
    params.add_float("camera_pitch", pitch, -89, 89, "camera elevation in degrees (drag the mouse)").with_step(5);
    params.add_float("camera_distance", distance, min_distance, 20, "camera distance from the origin (scroll)").with_step(0.1);
}

OrbitCamera orbit_camera(const Params& params) {
    OrbitCamera camera;
    camera.yaw_degrees = params.get_float("camera_yaw");
    camera.pitch_degrees = params.get_float("camera_pitch");
    camera.distance = params.get_float("camera_distance");
    return camera;
}

Session::~Session() {
    lab.reset();
    kit.reset();
    context.reset();
}

void Session::open(Backend backend, int extra_width) {
    ContextOptions context_options;
    context_options.backend = backend;
    context_options.profile = options.profile;
    const GlVersion needs = info.needs_in(options.profile);
    const std::string& needs_why = info.needs_why_in(options.profile);
    // Desktop: at least macOS's 4.1; ES: the lab's own lowest version, so a lab that says 3.0 is held to 3.0.
    const GlVersion least = options.profile == Profile::Es ? GlVersion{3, 0} : GlVersion{4, 1};
    context_options.version = options.gl.value_or(needs < least ? least : needs);
    if (!options.gl && options.profile != Profile::Es) context_options.up_to = info.uses;
    context_options.width = options.width + extra_width;
    context_options.height = options.height;
    context_options.title = title();
    context_options.keep_display = keep_display;
    // Only window mode shows its window: a headless mode on the window backend draws in a hidden one.
    context_options.visible = options.mode == RunMode::Window;
    try {
        context = create_context(context_options);
    } catch (const UnsupportedError& e) {
        throw UnsupportedError(std::string(e.what()) + "; " + info.id + " needs " +
                               api_name(options.profile, needs) + " (" + needs_why + ")");
    }
    std::fprintf(stderr, "%s: %s\n", info.id.c_str(), context->describe().c_str());
    context->require(needs, needs_why);
    kit = std::make_unique<LabKit>(*context, params, *assets, options.profile);
    for (const GlFeature* feature : gl_feature::kAll)
        if (!kit->allows(*feature))
            params.note_missing_feature(feature->name, std::string(feature->name) + ", which " +
                                                           api_name(options.profile, first_version_with(*feature, options.profile)) +
                                                           " has; this context is " + api_name(options.profile, kit->gl_version()));
    lab->setup(*kit);
    compiled_defines_ = param_defines(params);
}

Backend Session::headless_backend() {
    if (options.backend) return *options.backend;
    if (is_compiled(Backend::Egl)) return Backend::Egl;
    if (!told_hidden_window) {
        std::fprintf(stderr, "%s: no EGL in this build (Windows, macOS): drawing headless in a hidden window\n",
                     info.id.c_str());
        told_hidden_window = true;
    }
    return Backend::Window;
}

const Assets& Session::find_assets() {
    if (!assets) assets = std::make_unique<Assets>(lab_dir, executable);
    return *assets;
}

const std::vector<RenderCase>& Session::named_cases() {
    if (!cases) {
        cases = read_case_file(case_file(), info.id, defaults);
    }
    return *cases;
}

std::filesystem::path Session::case_file() {
    const Assets& a = find_assets();
    return info.case_file.empty() ? a.layout().case_file(info.id) : a.root() / info.case_file;
}

void Session::apply_case(const std::string& name) {
    std::string known;
    for (const auto& c : named_cases()) {
        if (c.name == name) {
            for (const auto& s : c.settings) params.set_assignment(s);
            return;
        }
        known += (known.empty() ? "" : ", ") + c.name;
    }
    throw Error("unknown case '" + name + "' (this lab has: " + known + ")");
}

void Session::apply_command_line_settings() {
    if (!options.case_name.empty()) apply_case(options.case_name);
    std::vector<std::string> names;
    for (const auto& a : options.assignments) {
        params.set_assignment(a);
        names.push_back(a.substr(0, a.find('=')));
    }
    // One rule everywhere: a setting that would change nothing is refused, naming what would enable it.
    params.check_applies(names, "--set ");
}

void Session::render_frame(const Frame& frame) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    lab->render(*kit, frame);
}

std::optional<std::string> Session::sync_params() {
    // The lab first: it may refuse the new values (a GL limit) with a clearer line than the shader
    // compiler would give for them.
    lab->params_changed(*kit);
    std::optional<std::string> error;
    std::vector<ShaderDefine> defines = param_defines(params);
    if (defines != compiled_defines_) {
        error = kit->shaders().rebuild_all(defines);
        compiled_defines_ = std::move(defines);
    }
    return error;
}

static void print_list(Session& s) {
    const std::vector<RenderCase>& cases = s.named_cases();
    const std::string uses = s.info.uses ? ", takes OpenGL " + s.info.uses->str() + "'s where the driver offers it" : "";
    std::printf("%s: %s (%s), needs OpenGL %s (%s%s) or OpenGL ES %s (%s)\nparameters:\n%s", s.info.id.c_str(),
                s.info.title.c_str(), s.variant.c_str(), s.info.needs.str().c_str(), s.info.needs_why.c_str(),
                uses.c_str(), s.info.needs_es.str().c_str(), s.info.needs_es_why.c_str(), s.params.describe().c_str());
    // The work of a frame at the size asked for (--size), with the settings asked for (--set, --case): from the
    // lab's own loop structure, so that a frame time can be held against what the device allows (scripts/kit bench).
    const Frame frame{s.options.width, s.options.height, 0.0};
    const FrameWork work = s.lab->frame_work(frame);
    std::printf("work per frame at %dx%d:\n%s", frame.width, frame.height,
                work.empty() ? "  (not stated)\n" : work.describe().c_str());
    std::printf("cases (%s; graded ones name their TODO):\n", s.case_file().lexically_normal().string().c_str());
    for (const auto& c : cases) {
        std::printf("  %-18s %s%s\n", c.name.c_str(), c.todo.empty() ? "(demo) " : ("(" + c.todo + ") ").c_str(), c.description.c_str());
        if (!c.settings.empty()) {
            std::printf("  %-18s", "");
            for (const auto& setting : c.settings) std::printf(" %s", setting.c_str());
            std::printf("\n");
        }
    }
}

void start_session(Session& session, std::unique_ptr<Lab> lab, const char* lab_dir, const char* variant,
                   const std::filesystem::path& executable) {
    session.lab = std::move(lab);
    session.info = session.lab->info();
    session.variant = variant;
    session.lab_dir = lab_dir;
    session.executable = executable;
    // The uniforms apply_transforms sets in core and ES: no parameter may have them.
    for (const char* uniform : {"uModelViewProjectionMatrix", "uModelViewMatrix", "uProjectionMatrix", "uNormalMatrix"})
        session.params.reserve_uniform(uniform, "the kit's transforms (apply_transforms)");
    session.lab->declare(session.params);
    session.defaults = session.params;
}

int with_exit_status(const Session& session, const std::string& stage, const std::function<int()>& body) {
    try {
        return body();
    } catch (const UnsupportedError& e) {
        std::fprintf(stderr, "%s: %s\n", session.info.id.c_str(), e.what());
        return kExitUnsupported;
    } catch (const Error& e) {
        std::fprintf(stderr, "%s: %s\n", session.info.id.c_str(), e.what());
        return kExitError;
    } catch (const std::filesystem::filesystem_error& e) {
        // A file or folder that could not be read or written: the user's to fix, and the message names it.
        std::fprintf(stderr, "%s: %s\n", session.info.id.c_str(), e.what());
        return kExitError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: internal error during %s: %s\n", session.info.id.c_str(), stage.c_str(), e.what());
        return kExitError;
    }
}

int run_lab(const LabFactory& make_lab, const char* lab_dir, const char* variant, int argc, const char* const* argv,
            const SweepPlanFactory& make_sweep_plan) {
    // On the heap: web mode hands it to the page, which draws with it after main() has returned.
    auto owned = std::make_unique<Session>();
    Session& session = *owned;
    std::string stage = "command line";
    return with_exit_status(session, stage, [&]() -> int {
        start_session(session, make_lab(), lab_dir, variant, Assets::executable_path(argc > 0 ? argv[0] : nullptr));
        session.make_sweep_plan = make_sweep_plan;
        try {
            session.options = parse_cli(argc, argv);
            // Served, each case brings its own settings: the command line's are not the cases'.
            if (session.options.serve && (!session.options.case_name.empty() || !session.options.assignments.empty()))
                throw Error("render --serve takes each case's settings from the grader, not --case or --set");
            session.apply_command_line_settings();
            const bool informational = session.options.help || session.options.version;
            if (session.options.mode == RunMode::Animate && !informational) check_animate_command(session);
            if (session.options.mode == RunMode::Sweep && !informational) check_sweep_command(session);
            if (session.options.mode != RunMode::Sweep && (!session.options.knob.empty() || !session.options.values.empty()))
                throw Error("--knob and --values are for sweep mode");
        } catch (const Error& e) {
            std::fprintf(stderr, "%s: %s\n", session.info.id.c_str(), e.what());
            return kExitUsage;
        }
        if (session.options.version) {
            std::printf("%s\n", version_line(session.info.id + (session.variant == std::string("solution") ? "_solution" : "")).c_str());
            return kExitOk;
        }
        if (session.options.help) {
            std::printf("%s: %s (%s)\n%s", session.info.id.c_str(), session.info.title.c_str(), variant,
                        cli_usage(argc > 0 ? argv[0] : session.info.id).c_str());
            return kExitOk;
        }
        if (session.options.mode == RunMode::List) {
            print_list(session);
            return kExitOk;
        }
        stage = "start";
        if (session.options.serve) return run_serve(make_lab, session);
        session.find_assets();
        switch (session.options.mode) {
        case RunMode::Window: return run_window(session);
        case RunMode::Render: return run_render(session);
        case RunMode::Sweep: return run_sweep(session);
        case RunMode::Animate: return run_animate(session);
        case RunMode::Compare: return run_compare(session);
        case RunMode::Web: return run_web(owned);
        case RunMode::List: break;
        }
        return kExitOk;
    });
}

}  // namespace gsv
