// Lab 03: time-varying line integral convolution with a 2D texture array.
// Seed: Bailey, "Using GPU Shaders for Visualization, Part 2" (texture arrays for time-varying data).
// T time slices of a flow go into ONE texture array; the fragment stage picks the slice of the
// playhead with a vec3 lookup whose third component is the layer. Beside it the same slices in a 3D
// texture (filtering runs across slices) and in T separate textures (one texture unit each).
#include "common/app/app.h"
#include "common/params/change_tracker.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/gl/texture.h"
#include "common/scene/mesh_data.h"
#include "support/flow/flow_field.h"
#include "support/flow/lic_contrast_pass.h"
#include "support/flow/lic_view_params.h"
#include "support/flow/lic_work.h"
#include "support/flow/noise.h"
#include "sweep_view.h"
#include "time_flow.h"

#include <string>
#include <vector>

namespace {

enum class Playhead { Time, Slice };
constexpr gsv::EnumName<Playhead> kPlayheads[] = {{Playhead::Time, "time"}, {Playhead::Slice, "slice"}};

class TextureArrayLab final : public gsv::Lab, public lab03::SweepView {
public:
    gsv::LabInfo info() const override { return {"lab03", "Texture arrays: time-varying LIC"}; }

    void declare(gsv::Params& p) override {
        lab03::SliceParams& s = slice_params_;
        s.field = p.add_enum("field", gsv::UnsteadyKind::DoubleGyre, gsv::kUnsteadyKindNames, lab03::kFields,
                             "the time-varying flow: analytic, or the sequence in field_file");
        s.field_file = p.add_file("field_file", "flows/vortex_street.flow", "a .flow sequence (data/README.md) for field=file")
                           .applies_when(s.field, {lab03::Field::File});
        s.slices = p.add_int("slices", 16, 1, 4096, "T: time slices stored over one period (of a file's frames, the one nearest each slice's time)")
                       .at_compile_time()
                       .accuracy_knob({"1", "2", "4", "8", "16", "32", "64"});
        s.blend = p.add_enum("blend", gsv::TimeBlend::Nearest, gsv::kTimeBlendNames, "the nearest slice, or linear in time between two")
                      .at_compile_time()
                      .series();
        s.storage = p.add_enum("storage", lab03::Storage::Array, lab03::kStorages,
                               "one 2D texture array, one 3D texture, or T separate 2D textures")
                        .at_compile_time()
                        .may_draw_the_same("the same slices held another way: the same picture, at another cost");
        s.time_wrap = p.add_enum("time_wrap", gsv::TimeWrap::Repeat, gsv::kTimeWrapNames, "a periodic flow wraps; any other stops at the last slice")
                          .at_compile_time()
                          .may_draw_the_same("the two differ only once the playhead is past the last slice");
        s.time = p.add_float("time", 3.3f, 0, 10, "the playhead over one period").with_step(0.1).animated();
        const auto playhead = p.add_enum("playhead", Playhead::Time, kPlayheads,
                                         "the slice axis from the playhead's time, or a position on it set directly (slice)")
                                  .at_compile_time();
        p.add_float("slice", 0, 0, 4095, "s, the position on the slice axis in slice units (playhead=slice): in [0, T) on a periodic axis, at most T - 1 on a clamped one")
            .with_step(0.25)
            .applies_when(playhead, {Playhead::Slice});
        length_ = p.add_int("length", 20, 0, 200, "LIC steps each way");
        s.grid = p.add_int("grid", 256, 16, 1024, "flow texels across (the domain is twice as wide as high)");
        s.speed = p.add_float("speed", 1.0, 0, 4, "largest speed, in flow texels per step").with_step(0.1);
        seed_ = p.add_int("seed", 1, 0, 1000000, "the white noise");
        view_ = gsv::add_lic_view_params(p);
        s.observer_velocity = view_.observer_velocity;
    }

    void setup(gsv::LabKit& kit) override {
        check_limits(kit);
        lic_ = &kit.program("lic", {"gsv/fullscreen.vert", "lic_time.frag"});
        quad_ = gsv::GpuMesh(gsv::make_fullscreen_quad(), kit.profile());
    }

    void params_changed(gsv::LabKit& kit) override { check_limits(kit); }

    void render(gsv::LabKit& kit, const gsv::Frame& frame) override {
        // The slices are uploaded only when what they were made from changes: playing the time costs no upload.
        const gsv::Params& p = kit.params();
        flow_.update(p, [&] { return lab03::make_time_flow(kit, slice_params_); });
        uploaded_.run_if_changed(p, [&] { upload(); }, flow_.version());
        noise_.update(p, [&] { return make_noise(frame); }, frame.width, frame.height);
        contrast_.draw(kit, frame, view_.contrast.get(), quad_, [&] {
            glDisable(GL_DEPTH_TEST);
            const gsv::ShaderProgram& program = kit.use(*lic_);
            program.bind("uNoise", *noise_);
            bind_flow(program);
            program.set("uFlowTexel", glm::vec2(1.0f / float(flow_->width), 1.0f / float(flow_->height)));
            quad_.draw();
        });
    }

    // lic_time.frag's loops, lab 02's with midpoint steps both ways, and flow_time.glsl's lookups a read of the flow:
    // two slices blended linearly are two lookups, except in the 3D texture, whose filter blends them in one.
    gsv::FrameWork frame_work(const gsv::Frame& frame) const override {
        const lab03::Storage storage = slice_params_.storage.get();
        const bool linear = slice_params_.blend.get() == gsv::TimeBlend::Linear;
        gsv::LicLoops loops;
        loops.width = frame.width;
        loops.height = frame.height;
        loops.length = length_.get();
        loops.flow_reads_per_step = 2;
        loops.flow_fetches_per_read = linear && storage != lab03::Storage::Volume ? 2 : 1;
        loops.input_texture = "R32F 2D";
        loops.flow_texture = storage == lab03::Storage::Array ? "RG32F 2D array" : storage == lab03::Storage::Volume ? "RG32F 3D" : "RG32F 2D";
        return gsv::lic_work(loops);
    }

    // What its sweep plan reads (sweep_view.h).
    gsv::LicContrast contrast() const override { return view_.contrast.get(); }
    const lab03::SliceParams& slice_params() const override { return slice_params_; }
    const gsv::FlowSequence& flow() const override { return *flow_; }

private:
    void check_limits(gsv::LabKit& kit) const { lab03::check_storage_limits(kit, slice_params_); }

    gsv::Texture make_noise(const gsv::Frame& frame) const {
        const std::vector<float> noise = gsv::white_noise(frame.width, frame.height, static_cast<std::uint64_t>(seed_.get()));
        return gsv::Texture::create_2d(frame.width, frame.height, gsv::TexelFormat::R32F, noise.data());
    }

    void upload() {
        const int slices = static_cast<int>(flow_->frames.size());
        const int w = flow_->width, h = flow_->height;
        // TODO(L03-T1): one buffer with all T slices, slice k straight after slice k - 1 (at
        // k * w * h * 2 floats): the layout glTexImage3D takes for an array and for a 3D texture alike.
        std::vector<float> packed;
//@solution L03-T1
        packed.reserve(static_cast<std::size_t>(slices) * static_cast<std::size_t>(w * h * 2));
        for (const gsv::FlowField& slice : flow_->frames)
            packed.insert(packed.end(), slice.velocity.begin(), slice.velocity.end());
//@starter
//        packed.assign(static_cast<std::size_t>(slices) * static_cast<std::size_t>(w * h * 2), 0.0f);
//        std::copy(flow_->frames[0].velocity.begin(), flow_->frames[0].velocity.end(), packed.begin());
//@end
        const lab03::Storage storage = slice_params_.storage.get();
        array_ = gsv::Texture();
        volume_ = gsv::Texture();
        separate_.clear();
        gsv::Sampling sampling;  // linear in s and t, clamped at the borders of the domain
        if (storage == lab03::Storage::Array) {
            array_ = gsv::Texture::create_2d_array(w, h, slices, gsv::TexelFormat::RG32F, packed.data(), sampling);
        } else if (storage == lab03::Storage::Volume) {
            sampling.wrap_r = slice_params_.time_wrap.get() == gsv::TimeWrap::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
            volume_ = gsv::Texture::create_3d(w, h, slices, gsv::TexelFormat::RG32F, packed.data(), sampling);
        } else {
            for (const gsv::FlowField& slice : flow_->frames)
                separate_.push_back(gsv::Texture::create_2d(w, h, gsv::TexelFormat::RG32F, slice.velocity.data(), sampling));
        }
    }

    // T separate textures take a unit each and are bound every frame: the cost (and the unit limit) the array
    // removes.
    void bind_flow(const gsv::ShaderProgram& program) const override {
        if (array_.id()) {
            program.bind("uFlowArray", array_);
        } else if (volume_.id()) {
            program.bind("uFlowVolume", volume_);
        } else {
            for (std::size_t k = 0; k < separate_.size(); ++k)
                program.bind("uFlowSlices[" + std::to_string(k) + "]", separate_[k]);
        }
    }

    lab03::SliceParams slice_params_;
    gsv::Param<int> seed_, length_;
    gsv::LicViewParams view_;
    const gsv::ShaderLibrary::Entry* lic_ = nullptr;
    gsv::GpuMesh quad_;
    gsv::Tracked<gsv::FlowSequence> flow_;
    gsv::ChangeTracker uploaded_;
    gsv::Tracked<gsv::Texture> noise_;
    gsv::Texture array_, volume_;
    std::vector<gsv::Texture> separate_;
    gsv::LicContrastPass contrast_;
};

}  // namespace

int main(int argc, char** argv) { return gsv::run_lab<TextureArrayLab>(argc, argv); }
