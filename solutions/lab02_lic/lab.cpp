// Lab 02: line integral convolution (LIC) in a fragment shader.
// Seed: Bailey, "Using GPU Shaders for Visualization, Part 2"; Cabral and Leedom, "Imaging Vector Fields
// Using Line Integral Convolution" (SIGGRAPH 1993).
// The lesson is in the shaders (lic.frag, streamline.glsl); this file makes the two textures LIC reads
// (white noise or a photograph, and the flow in texels per step) and draws one full-screen quad.
#include "common/app/app.h"
#include "common/params/change_tracker.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/gl/texture.h"
#include "common/image/image.h"
#include "common/scene/mesh_data.h"
#include "support/flow/flow_field.h"
#include "support/flow/lic_contrast_pass.h"
#include "support/flow/lic_view_params.h"
#include "support/flow/moving_frame.h"
#include "support/flow/noise.h"
#ifdef GSV_HAVE_REFERENCE
#include "reference/lab02_lic/exact_lic_images.h"  // the instructor's exact LIC (cmake/labs.cmake)
#endif

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

class LicLab final : public gsv::Lab {
public:
    gsv::LabInfo info() const override { return {"lab02", "Line integral convolution"}; }

    void declare(gsv::Params& p) override {
        p.add_choice("field", "rotation", {"rotation", "saddle", "source", "double_gyre", "vortices", "swirl", "file"},
                     "the flow: analytic fields, a swirl confined to a disc for the photograph, or field_file");
        p.add_file("field_file", "flows/vortex_street.flow",
                   "a .flow file (format in data/README.md) for field=file; of a sequence, the frame at `time`")
            .applies_when("field", {"file"});
        p.add_choice("input", "noise", {"noise", "photo"}, "what LIC smears: white noise, or a photograph");
        p.add_int("length", 25, 0, 200, "steps each way along the streamline")
            .accuracy_knob({"1", "2", "5", "10", "25", "50", "100"});
        p.add_choice("streaks", "both", {"both", "forward"},
                     "streamlines followed both ways (a centred kernel), or forward only: one-sided streaks, the first loop alone")
            .at_compile_time();
        p.add_choice("step", "euler", {"euler", "midpoint"}, "first-order (Euler) or second-order (midpoint) steps")
            .at_compile_time()
            .series();
        p.add_effect("normalized", false, "unit steps along the flow, whatever its speed");
        p.add_float("speed", 1.0, 0, 4, "the field's largest speed, in texels per step").with_step(0.1);
        p.add_int("seed", 1, 0, 1000000, "the white noise and the vortices");
        p.add_float("time", 0, 0, 10, "the double gyre's time; the frame of a .flow sequence").with_step(0.5).animated()
            .applies_when("field", {"double_gyre", "file"});
        p.add_float("swirl_radius", 0.28, 0.05, 0.7, "radius of the swirl around the photograph's face").with_step(0.02).applies_when("field", {"swirl"});
        gsv::add_lic_view_params(p);
    }

    void setup(gsv::LabKit& kit) override {
        lic_ = &kit.program("lic", {"gsv/fullscreen.vert", "lic.frag"});
        quad_ = gsv::GpuMesh(gsv::make_fullscreen_quad(), kit.profile());
        photo_ = gsv::read_image(kit.assets().data_file("images/grace_hopper.jpg"));
    }

    void render(gsv::LabKit& kit, const gsv::Frame& frame) override {
        // Each texture is remade only when what it was made from changes: not for `length` or the step, and not
        // on every frame while `time` plays a field from a file (which is read once).
        flow_.update(kit.params(), [&] { return make_flow_texture(kit, frame); }, frame.width, frame.height);
        input_.update(kit.params(), [&] { return make_input_texture(kit, frame); }, frame.width, frame.height);
        contrast_.draw(kit, frame, gsv::lic_contrast_from_name(kit.params().get_choice("contrast")), quad_, [&] {
            glDisable(GL_DEPTH_TEST);
            const gsv::ShaderProgram& program = kit.use(*lic_);
            program.bind("uInput", *input_);
            program.bind("uFlow", *flow_);
            quad_.draw();
        });
    }

#ifdef GSV_HAVE_REFERENCE
    // Where the field has a formula and the input is the noise, each image of the sweep is measured against LIC of
    // the same length along the field's exact streamlines, so that the error is the step's alone: against a longer
    // LIC, Euler's and midpoint's errors came out the same. The exact LIC is the instructor's (reference/): a
    // student's sweep measures against the long midpoint LIC below.
    std::optional<gsv::Image> sweep_exact_image(gsv::LabKit& kit, const gsv::Frame& frame) override {
        const auto& p = kit.params();
        gsv::check_sweepable(gsv::lic_contrast_from_name(p.get_choice("contrast")));
        exact_applies_ = p.get_choice("field") != "file" && p.get_choice("input") == "noise";
        if (!exact_applies_) return std::nullopt;
        return exact_.image(p, frame, [&] { return exact_field(p, frame); }, [&] { return noise(p, frame); });
    }
#endif
    std::string sweep_reference_name() const override {
#ifdef GSV_HAVE_REFERENCE
        if (exact_applies_) return lab02::ExactLicImages::description();
#endif
        return "midpoint LIC of length 200, there being no exact LIC of a field from a file, of the photograph, or in a build "
               "without the instructor's reference/: a longer filter, so the error measures the length as well as the "
               "accuracy";
    }
    std::vector<std::string> sweep_reference() const override { return {"step=midpoint", "length=200"}; }
    // Called at every point of any sweep, the lab's knob or another.
    gsv::SweepMetrics sweep_metrics(gsv::LabKit& kit, const gsv::Frame&) override {
        gsv::check_sweepable(gsv::lic_contrast_from_name(kit.params().get_choice("contrast")));
        return {};
    }

private:
    // One flow texel per pixel: a step of one texel is a step of one pixel. The field is scaled to `speed` in the
    // lab's frame, then seen from the observer's.
    gsv::Texture make_flow_texture(gsv::LabKit& kit, const gsv::Frame& frame) {
        const auto& p = kit.params();
        const std::string field = p.get_choice("field");
        const double speed = p.get_float("speed");
        const gsv::FlowField lab_frame =
            field == "file"    ? field_from_file(kit, speed)
            : field == "swirl" ? gsv::make_photo_swirl(frame.width, frame.height, speed, kSwirlCentre.x, kSwirlCentre.y,
                                                       p.get_float("swirl_radius"))
                               : gsv::make_flow(gsv::flow_kind_from_name(field), frame.width, frame.height, speed,
                                                p.get_float("time"), static_cast<std::uint64_t>(p.get_int("seed")));
        const gsv::FlowField flow = gsv::seen_from_moving_frame(lab_frame, observer_velocity(p));
        return gsv::Texture::create_2d(flow.width, flow.height, gsv::TexelFormat::RG32F, flow.velocity.data());
    }

    gsv::Texture make_input_texture(gsv::LabKit& kit, const gsv::Frame& frame) const {
        const auto& p = kit.params();
        if (p.get_choice("input") == "photo") {
            gsv::Image bottom_up = photo_;
            gsv::flip_rows(bottom_up);
            return gsv::Texture::create_2d(photo_.width, photo_.height, gsv::TexelFormat::RGBA8, bottom_up.rgba.data());
        }
        // Grey noise in all three channels, in float: a texel's value is exactly what the CPU drew.
        const std::vector<float> grey = noise(p, frame);
        std::vector<float> rgb(grey.size() * 3);
        for (std::size_t i = 0; i < grey.size(); ++i) rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = grey[i];
        return gsv::Texture::create_2d(frame.width, frame.height, gsv::TexelFormat::RGB32F, rgb.data());
    }

    static std::vector<float> noise(const gsv::Params& p, const gsv::Frame& frame) {
        return gsv::white_noise(frame.width, frame.height, static_cast<std::uint64_t>(p.get_int("seed")));
    }

    // The observer's velocity in texels per step.
    static double observer_velocity(const gsv::Params& p) {
        return static_cast<double>(p.get_float("observer_velocity")) * p.get_float("speed");
    }

    // The field make_flow_texture samples, everywhere: for the sweep's exact streamlines.
    static gsv::VelocityAt exact_field(const gsv::Params& p, const gsv::Frame& frame) {
        const std::string field = p.get_choice("field");
        const double speed = p.get_float("speed");
        gsv::VelocityAt lab_frame =
            field == "swirl" ? gsv::analytic_photo_swirl(frame.width, frame.height, speed, kSwirlCentre.x, kSwirlCentre.y,
                                                         p.get_float("swirl_radius"))
                             : gsv::analytic_flow(gsv::flow_kind_from_name(field), frame.width, frame.height, speed,
                                                  p.get_float("time"), static_cast<std::uint64_t>(p.get_int("seed")));
        return gsv::seen_from_moving_frame(std::move(lab_frame), observer_velocity(p));
    }

    // A file's field keeps its own grid (the shader steps in flow texels) and is rescaled like the
    // analytic ones, so `speed` means the same for every field. Of a sequence, `time` in [0, 10] picks a
    // frame, as it moves the double gyre through its period.
    gsv::FlowField field_from_file(gsv::LabKit& kit, double speed) {
        const auto& p = kit.params();
        file_.update(p, [&] { return gsv::load_flow_sequence(kit.assets().user_file(p.get_file("field_file"))); });
        const int frames = static_cast<int>(file_->frames.size());
        const int index = std::min(frames - 1, static_cast<int>(p.get_float("time") / 10.0 * frames));
        gsv::FlowField field = file_->frames[static_cast<std::size_t>(index)];
        const float fastest = field.max_speed();
        if (fastest > 0)
            for (float& v : field.velocity) v = static_cast<float>(v * (speed / fastest));
        return field;
    }

    // Grace Hopper's face in the photograph, in texture coordinates: what the swirl turns.
    static constexpr glm::dvec2 kSwirlCentre{0.5, 0.62};

    const gsv::ShaderLibrary::Entry* lic_ = nullptr;
    gsv::GpuMesh quad_;
    gsv::Image photo_;
    gsv::Tracked<gsv::Texture> input_, flow_;
    gsv::Tracked<gsv::FlowSequence> file_;
    gsv::LicContrastPass contrast_;
#ifdef GSV_HAVE_REFERENCE
    lab02::ExactLicImages exact_;
    bool exact_applies_ = false;  // the last sweep point was measured against the exact LIC
#endif
};

}  // namespace

int main(int argc, char** argv) { return gsv::run_lab<LicLab>(argc, argv); }
