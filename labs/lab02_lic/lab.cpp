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
#include "support/flow/lic_work.h"
#include "support/flow/lic_view_params.h"
#include "support/flow/moving_frame.h"
#include "support/flow/noise.h"
#include "sweep_view.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

// The flows: support/flow's analytic ones (gsv::kFlowKindNames), then the lab's own two.
enum class Field { Swirl, File };
constexpr gsv::EnumName<Field> kFields[] = {{Field::Swirl, "swirl"}, {Field::File, "file"}};
using FieldChoice = gsv::OneOf<gsv::FlowKind, Field>;
enum class Input { Noise, Photo };
constexpr gsv::EnumName<Input> kInputs[] = {{Input::Noise, "noise"}, {Input::Photo, "photo"}};

class LicLab final : public gsv::Lab, public lab02::SweepView {
public:
    gsv::LabInfo info() const override { return {"lab02", "Line integral convolution"}; }

    void declare(gsv::Params& p) override {
        field_ = p.add_enum("field", gsv::FlowKind::Rotation, gsv::kFlowKindNames, kFields,
                            "the flow: analytic fields, a swirl confined to a disc for the photograph, or field_file");
        field_file_ = p.add_file("field_file", "flows/vortex_street.flow",
                                 "a .flow file (format in data/README.md) for field=file; of a sequence, the frame at `time`")
                          .applies_when(field_, {Field::File});
        // Only the lab reads it: it picks what goes into the texture uInput.
        input_ = p.add_enum("input", Input::Noise, kInputs, "what LIC smears: white noise, or a photograph").without_uniform();
        length_ = p.add_int("length", 25, 0, 200, "steps each way along the streamline")
            .accuracy_knob({"1", "2", "5", "10", "25", "50", "100"});
        streaks_ = p.add_choice("streaks", "both", {"both", "forward"},
                     "streamlines followed both ways (a centred kernel), or forward only: one-sided streaks, the first loop alone")
            .at_compile_time();
        step_ = p.add_choice("step", "euler", {"euler", "midpoint"}, "first-order (Euler) or second-order (midpoint) steps")
            .at_compile_time()
            .series();
        p.add_effect("normalized", false, "unit steps along the flow, whatever its speed");
        speed_ = p.add_float("speed", 1.0, 0, 4, "the field's largest speed, in texels per step").with_step(0.1);
        seed_ = p.add_int("seed", 1, 0, 1000000, "the white noise and the vortices");
        time_ = p.add_float("time", 0, 0, 10, "the double gyre's time; the frame of a .flow sequence").with_step(0.5).animated()
                    .applies_when(field_, {gsv::FlowKind::DoubleGyre, Field::File});
        swirl_radius_ = p.add_float("swirl_radius", 0.28, 0.05, 0.7, "radius of the swirl around the photograph's face")
                            .with_step(0.02)
                            .applies_when(field_, {Field::Swirl});
        view_ = gsv::add_lic_view_params(p);
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
        input_texture_.update(kit.params(), [&] { return make_input_texture(frame); }, frame.width, frame.height);
        contrast_.draw(kit, frame, view_.contrast.get(), quad_, [&] {
            glDisable(GL_DEPTH_TEST);
            const gsv::ShaderProgram& program = kit.use(*lic_);
            program.bind("uInput", *input_texture_);
            program.bind("uFlow", *flow_);
            quad_.draw();
        });
    }

    // lic.frag's loops: the input once a pixel and once a step, the flow once a step (Euler) or twice (midpoint).
    gsv::FrameWork frame_work(const gsv::Frame& frame) const override {
        gsv::LicLoops loops;
        loops.width = frame.width;
        loops.height = frame.height;
        loops.length = length_.get();
        loops.directions = streaks_.get() == "both" ? 2 : 1;
        loops.flow_reads_per_step = step_.get() == "midpoint" ? 2 : 1;
        loops.input_texture = input_.get() == Input::Photo ? "RGBA8 2D" : "RGB32F 2D";
        loops.flow_texture = "RG32F 2D";
        // The contrast's tone-curve pass reads with texelFetch (unfiltered) after a readback: the LIC pass is the work.
        return gsv::lic_work(loops);
    }

    // What its sweep plan reads (sweep_view.h).
    gsv::LicContrast contrast() const override { return view_.contrast.get(); }
    bool field_has_formula() const override { return field_.get() != Field::File && input_.get() == Input::Noise; }

private:
    // One flow texel per pixel: a step of one texel is a step of one pixel. The field is scaled to `speed` in the
    // lab's frame, then seen from the observer's.
    gsv::Texture make_flow_texture(gsv::LabKit& kit, const gsv::Frame& frame) {
        const FieldChoice field = field_.get();
        const double speed = speed_.get();
        const gsv::FlowField lab_frame =
            field == Field::File    ? field_from_file(kit, speed)
            : field == Field::Swirl ? gsv::make_photo_swirl(frame.width, frame.height, speed, kSwirlCentre.x, kSwirlCentre.y,
                                                            swirl_radius_.get())
                                    : gsv::make_flow(*field.as<gsv::FlowKind>(), frame.width, frame.height, speed, time_.get(), seed());
        const gsv::FlowField flow = gsv::seen_from_moving_frame(lab_frame, observer_velocity());
        return gsv::Texture::create_2d(flow.width, flow.height, gsv::TexelFormat::RG32F, flow.velocity.data());
    }

    gsv::Texture make_input_texture(const gsv::Frame& frame) const {
        if (input_.get() == Input::Photo) {
            gsv::Image bottom_up = photo_;
            gsv::flip_rows(bottom_up);
            return gsv::Texture::create_2d(photo_.width, photo_.height, gsv::TexelFormat::RGBA8, bottom_up.rgba.data());
        }
        // Grey noise in all three channels, in float: a texel's value is exactly what the CPU drew.
        const std::vector<float> grey = noise(frame);
        std::vector<float> rgb(grey.size() * 3);
        for (std::size_t i = 0; i < grey.size(); ++i) rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = grey[i];
        return gsv::Texture::create_2d(frame.width, frame.height, gsv::TexelFormat::RGB32F, rgb.data());
    }

    std::uint64_t seed() const { return static_cast<std::uint64_t>(seed_.get()); }

    std::vector<float> noise(const gsv::Frame& frame) const override {
        return gsv::white_noise(frame.width, frame.height, seed());
    }

    // The observer's velocity in texels per step.
    double observer_velocity() const { return static_cast<double>(view_.observer_velocity.get()) * speed_.get(); }

    // The field make_flow_texture samples, everywhere: for the sweep's exact streamlines.
    gsv::VelocityAt exact_field(const gsv::Frame& frame) const override {
        const FieldChoice field = field_.get();
        const double speed = speed_.get();
        gsv::VelocityAt lab_frame =
            field == Field::Swirl ? gsv::analytic_photo_swirl(frame.width, frame.height, speed, kSwirlCentre.x, kSwirlCentre.y,
                                                              swirl_radius_.get())
                                  : gsv::analytic_flow(*field.as<gsv::FlowKind>(), frame.width, frame.height, speed, time_.get(), seed());
        return gsv::seen_from_moving_frame(std::move(lab_frame), observer_velocity());
    }

    // A file's field keeps its own grid (the shader steps in flow texels) and is rescaled like the
    // analytic ones, so `speed` means the same for every field. Of a sequence, `time` in [0, 10] picks a
    // frame, as it moves the double gyre through its period.
    gsv::FlowField field_from_file(gsv::LabKit& kit, double speed) {
        file_.update(kit.params(), [&] { return gsv::load_flow_sequence(kit.assets().user_file(field_file_.get())); });
        const int frames = static_cast<int>(file_->frames.size());
        const int index = std::min(frames - 1, static_cast<int>(time_.get() / 10.0 * frames));
        gsv::FlowField field = file_->frames[static_cast<std::size_t>(index)];
        const float fastest = field.max_speed();
        if (fastest > 0)
            for (float& v : field.velocity) v = static_cast<float>(v * (speed / fastest));
        return field;
    }

    // Grace Hopper's face in the photograph, in texture coordinates: what the swirl turns.
    static constexpr glm::dvec2 kSwirlCentre{0.5, 0.62};

    gsv::EnumParam<FieldChoice> field_;
    gsv::EnumParam<Input> input_;
    gsv::Param<std::string> field_file_;
    gsv::Param<float> speed_, time_, swirl_radius_;
    gsv::Param<int> seed_, length_;
    gsv::Param<std::string> streaks_, step_;
    gsv::LicViewParams view_;
    const gsv::ShaderLibrary::Entry* lic_ = nullptr;
    gsv::GpuMesh quad_;
    gsv::Image photo_;
    gsv::Tracked<gsv::Texture> input_texture_, flow_;
    gsv::Tracked<gsv::FlowSequence> file_;
    gsv::LicContrastPass contrast_;
};

}  // namespace

int main(int argc, char** argv) { return gsv::run_lab<LicLab>(argc, argv); }
