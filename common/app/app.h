#pragma once
// The lab app. A lab declares what it is (parameters with their ranges, effects and accuracy knob) and how it
// draws; its named cases come from its public case file (common/params/case_file.h). The framework gives it the
// window, headless rendering, sweeps, the command line, hot reload, timing and image output. A lab's main() is
// one line: return gsv::run_lab<MyLab>(argc, argv);
#include "common/app/assets.h"
#include "common/params/case_file.h"
#include "common/app/depth_readback.h"
#include "common/app/exit_status.h"
#include "common/app/sweep_plan.h"
#include "common/window/inspect_stage.h"
#include "common/params/params.h"
#include "common/context/context.h"
#include "common/gl/gl_features.h"
#include "common/image/image.h"
#include "common/image/legend.h"
#include "common/io/data_array.h"
#include "common/scene/transforms.h"
#include "common/shader/shader_library.h"
#include "common/shader/transform_uniforms.h"
#include "common/timing/frame_work.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gsv {

struct LabInfo {
    std::string id;               // "lab01": names outputs and reports
    std::string title;            // "GLSL basics and Gooch shading"
    GlVersion needs{4, 1};        // labs other than 05 run on macOS's 4.1 core
    std::string needs_why = "the kit's baseline";
    // A desktop version above `needs` whose features the lab takes where the driver offers them, and does without
    // below it (lab 05: 4.3's compute shaders, transform feedback on macOS's 4.1). The run holds to it, not to `needs`,
    // unless --gl says otherwise. None: the lab holds to `needs`.
    std::optional<GlVersion> uses{};
    // Its named cases, relative to the kit's root; empty: the public case file (KitLayout::case_file).
    std::string case_file{};
    // The lowest OpenGL ES version it runs on with --profile es: 3.0 is WebGL 2's feature set.
    GlVersion needs_es{3, 0};
    std::string needs_es_why = "WebGL 2's feature set";

    GlVersion needs_in(Profile profile) const { return profile == Profile::Es ? needs_es : needs; }
    const std::string& needs_why_in(Profile profile) const { return profile == Profile::Es ? needs_es_why : needs_why; }
};

struct Frame {
    int width = 0, height = 0;
    double time_s = 0;  // seconds since start in window mode; 0 headless, so images are reproducible
    // Window mode: a lab may spread work over frames (lab 05 catches its simulation up a few steps a frame).
    // Headless, every frame must show the full result of the current settings.
    bool interactive = false;
    float aspect() const { return height > 0 ? static_cast<float>(width) / static_cast<float>(height) : 1.0f; }
};

class LabKit;

// What a student's lab implements. What its sweeps measure it against is not here: that is the instructor's, its sweep
// plan (common/app/sweep_plan.h, reference/<lab dir>/sweep_plan.cpp).
class Lab {
public:
    virtual ~Lab() = default;
    virtual LabInfo info() const = 0;
    virtual void declare(Params& params) = 0;
    virtual void setup(LabKit& kit) = 0;
    virtual void render(LabKit& kit, const Frame& frame) = 0;
    // A parameter changed (window keys, the next sweep point or animation frame): rebuild what depends on it,
    // e.g. a mesh.
    virtual void params_changed(LabKit&) {}
    // What a frame with the current settings asks of the device (common/timing/frame_work.h): texture fetches by
    // format, storage bytes, fragments, arithmetic, counted from the lab's own loops; shown by `list`, in sweeps and
    // against the device's ceilings. Empty: not stated.
    virtual FrameWork frame_work(const Frame&) const { return {}; }
    // What render mode writes beside the image for the grader to compare with the reference's; most labs none.
    virtual std::vector<DataArray> readback(LabKit&) { return {}; }
    // Where colour is data (a height, a speed, an intensity's colour and opacity): what the colours of the frame last
    // drawn stand for, sampled from the same shaders (common/app/legend_probe.h) or the same C++ tables that drew
    // it, so the legend cannot drift from the picture. `render --legend` draws it beside the image and the
    // window's panel live. None: this lab's colours, with these settings, stand for no value (shading, LIC).
    virtual std::optional<Legend> legend(LabKit&) { return std::nullopt; }
    // Visual debugging: the intermediate images of the last frame (lab 06: every port of its network), written
    // into `folder` (created); returns the files. Called by `render --debug-images` and by window screenshots.
    virtual std::vector<std::filesystem::path> write_debug_images(LabKit&, const std::filesystem::path&) { return {}; }
    // The same, live in the window: the stages of the last frame, and one of their images (alpha and depth in
    // pseudo-colour) read back now; none when it has none (its stage failed).
    virtual std::vector<InspectStage> inspect_stages() const { return {}; }
    virtual std::optional<Image> inspect_image(LabKit&, const std::string&) { return std::nullopt; }
};

// The margin table's 8-bit filter stand-in (shaders/gsv/texel_snap.glsl): GSV_TEXEL_SNAP=N in the environment makes
// every lab shader snap its texture coordinates to 1/N of a texel; none when it is unset. Throws gsv::Error, one line,
// on a value that is not a whole number 2..65536.
std::optional<ShaderDefine> texel_snap_define();

// What a lab gets from the framework.
class LabKit {
public:
    LabKit(Context& context, Params& params, const Assets& assets, Profile profile);

    const Params& params() const { return params_; }
    Profile profile() const { return profile_; }
    GlVersion gl_version() const { return context_.effective_version(); }
    // Whether this run's profile and version have the feature (common/gl/gl_features.h); require() stops the
    // run (exit 3) where it does not, naming what asked for it and the version that has it.
    bool allows(const GlFeature& feature) const { return gsv::allows(feature, profile_, gl_version()); }
    void require(const GlFeature& feature, const std::string& asked_by) const;
    const Assets& assets() const { return assets_; }
    Context& context() { return context_; }

    // A program from the lab's shader files (e.g. {"gooch.vert", "gooch.frag"}), built with the
    // parameters' #defines and kept up to date by the framework. `captured`: vertex outputs written to buffers by
    // transform feedback (ProgramSpec::captured).
    const ShaderLibrary::Entry& program(const std::string& name, const std::vector<std::string>& files,
                                        const std::vector<std::string>& captured = {});
    // Binds the program and sets every runtime parameter as its uniform; set the rest yourself.
    const ShaderProgram& use(const ShaderLibrary::Entry& entry) const;
    // The #defines the parameters give every program (common/shader/param_uniforms.h).
    std::vector<ShaderDefine> defines() const;
    void set_transforms(const ShaderProgram& program, const Transforms& transforms) const {
        apply_transforms(program, transforms, profile_);
    }

    ShaderLibrary& shaders() { return shaders_; }

    // A target's depth buffer, width * height values in [0, 1], row 0 = top, in every profile (common/app/depth_readback.h).
    std::vector<float> read_depth(const Framebuffer& target) { return depth_readback_.read(*this, target); }

    // An interactive frame that did only part of what its values ask (lab 05 catches its simulation up a few steps a
    // frame): the page, which draws only on a change, draws again until the lab stops asking (the window draws on).
    // `progress` says how far the picture has got ("catching up: step 12 of 40"), shown while it is behind.
    void ask_for_another_frame(std::string progress = {}) {
        another_frame_ = true;
        progress_ = std::move(progress);
    }
    bool take_another_frame_request() {
        const bool asked = another_frame_;
        another_frame_ = false;
        if (!asked) progress_.clear();
        return asked;
    }
    // The progress the last frame that asked for another gave; empty once a frame did all its work.
    const std::string& progress() const { return progress_; }

private:
    Context& context_;
    Params& params_;
    const Assets& assets_;
    Profile profile_;
    ShaderLibrary shaders_;
    DepthReadback depth_readback_;
    bool another_frame_ = false;
    std::string progress_;
};

// Declares the camera parameters (camera_yaw, camera_pitch, camera_distance) that window mode drives with
// the mouse and that cases and hidden grader cases set.
// min_distance: how close the camera may come; the default keeps it outside the unit sphere the labs
// frame, and lab 06 lets it into the volume.
void add_orbit_camera(Params& params, float yaw, float pitch, float distance, float min_distance = 1.2f);
OrbitCamera orbit_camera(const Params& params);

// Makes the lab anew: `render --serve` starts each case from a lab object of its own.
using LabFactory = std::function<std::unique_ptr<Lab>()>;
// Makes the plan a sweep measures the lab with (common/app/sweep_plan.h); none: the default plan.
using SweepPlanFactory = std::function<std::unique_ptr<SweepPlan>(Lab&)>;

int run_lab(const LabFactory& make_lab, const char* lab_dir, const char* variant, int argc, const char* const* argv,
            const SweepPlanFactory& make_sweep_plan = {});

#ifdef GSV_LAB_DIR  // defined for lab executables by cmake/labs.cmake
#ifdef GSV_HAVE_REFERENCE
// The lab's sweep plan, reference/<lab dir>/sweep_plan.cpp: linked, and GSV_HAVE_REFERENCE defined, only in a solution
// target where the instructor's reference/ is (cmake/labs.cmake). Elsewhere sweeps take the default plan.
std::unique_ptr<SweepPlan> make_lab_sweep_plan(Lab& lab);
#endif
template <class L>
int run_lab(int argc, char** argv) {
    SweepPlanFactory make_sweep_plan;
#ifdef GSV_HAVE_REFERENCE
    make_sweep_plan = make_lab_sweep_plan;
#endif
    return run_lab([] { return std::unique_ptr<Lab>(std::make_unique<L>()); }, GSV_LAB_DIR, GSV_LAB_VARIANT, argc, argv,
                   make_sweep_plan);
}
#endif

}  // namespace gsv
