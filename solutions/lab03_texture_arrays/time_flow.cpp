#include "time_flow.h"

#include "common/core/error.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "support/flow/moving_frame.h"
#include "support/flow/time_slices.h"

#include <algorithm>
#include <cmath>

namespace lab03 {
namespace {

constexpr double kPeriod = 10.0;        // flow_time.glsl's kPeriod
constexpr int kErrorTimes = 37;         // playheads over the period for the temporal error (prime)
constexpr double kMaxSliceBytes = 1024.0 * 1024 * 1024;

gsv::TimeWrap wrap_of(const gsv::Params& p) {
    return p.get_choice("time_wrap") == "repeat" ? gsv::TimeWrap::Repeat : gsv::TimeWrap::Clamp;
}
gsv::TimeBlend blend_of(const gsv::Params& p) {
    return p.get_choice("blend") == "linear" ? gsv::TimeBlend::Linear : gsv::TimeBlend::Nearest;
}

int gl_limit(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

// The flow of `sequence` at the playhead as the shader should sample it, at texel (x, y).
glm::dvec2 mixed(const gsv::FlowSequence& sequence, const gsv::SliceMix& m, int x, int y) {
    const glm::dvec2 a(sequence.frames[static_cast<std::size_t>(m.first)].at(x, y));
    const glm::dvec2 b(sequence.frames[static_cast<std::size_t>(m.second)].at(x, y));
    return a + m.weight * (b - a);
}

// The flow at each of `times` in the lab's frame: an analytic flow sampled there (one scale for any set of times),
// or a file's frames, spread over the period like slices, blended linearly in time.
gsv::FlowSequence lab_frame_flow_at_times(gsv::LabKit& kit, const std::vector<double>& times) {
    const auto& p = kit.params();
    const std::string field = p.get_choice("field");
    const double speed = p.get_float("speed");
    if (field != "file") {
        const int grid = p.get_int("grid");
        return gsv::make_unsteady_flow(gsv::unsteady_kind_from_name(field), grid, std::max(1, grid / 2), times, speed);
    }
    const gsv::FlowSequence file = gsv::load_flow_sequence(kit.assets().user_file(p.get_file("field_file")));
    const float fastest = file.max_speed();
    const double scale = fastest > 0 ? speed / fastest : 0.0;
    gsv::FlowSequence out;
    out.width = file.width;
    out.height = file.height;
    for (double time : times) {
        const gsv::SliceMix m = gsv::slice_mix(time, kPeriod, static_cast<int>(file.frames.size()), wrap_of(p),
                                               gsv::TimeBlend::Linear);
        gsv::FlowField frame = file.frames[static_cast<std::size_t>(m.first)];
        for (int y = 0; y < frame.height; ++y)
            for (int x = 0; x < frame.width; ++x) {
                const glm::dvec2 v = mixed(file, m, x, y) * scale;
                const std::size_t i = 2 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(x));
                frame.velocity[i] = static_cast<float>(v.x);
                frame.velocity[i + 1] = static_cast<float>(v.y);
            }
        out.frames.push_back(std::move(frame));
    }
    return out;
}

// The same seen by the observer, who moves at observer_velocity times `speed` flow texels per step.
gsv::FlowSequence flow_at_times(gsv::LabKit& kit, const std::vector<double>& times) {
    const auto& p = kit.params();
    return gsv::seen_from_moving_frame(lab_frame_flow_at_times(kit, times),
                                       static_cast<double>(p.get_float("observer_velocity")) * p.get_float("speed"));
}

std::vector<double> slice_times(int slices) {
    std::vector<double> times;
    for (int k = 0; k < slices; ++k) times.push_back(kPeriod * k / slices);
    return times;
}

}  // namespace

gsv::FlowSequence make_time_flow(gsv::LabKit& kit) { return flow_at_times(kit, slice_times(kit.params().get_int("slices"))); }

void check_storage_limits(const gsv::LabKit& kit) {
    const gsv::Params& p = kit.params();
    const int slices = p.get_int("slices");
    const int grid = p.get_int("grid");
    const double bytes = 8.0 * slices * grid * std::max(1, grid / 2);
    if (p.get_choice("field") != "file" && bytes > kMaxSliceBytes)
        throw gsv::Error("slices=" + std::to_string(slices) + " at grid=" + std::to_string(grid) + " need " +
                         std::to_string(static_cast<long long>(bytes / (1 << 20))) + " MiB of flow; the lab allows 1024");
    const std::string storage = p.get_choice("storage");
    if (storage == "array" && slices > gl_limit(GL_MAX_ARRAY_TEXTURE_LAYERS))
        throw gsv::UnsupportedError("slices=" + std::to_string(slices) + " exceeds GL_MAX_ARRAY_TEXTURE_LAYERS = " +
                                    std::to_string(gl_limit(GL_MAX_ARRAY_TEXTURE_LAYERS)) + " on this GPU");
    if (storage == "volume" && slices > gl_limit(GL_MAX_3D_TEXTURE_SIZE))
        throw gsv::UnsupportedError("slices=" + std::to_string(slices) + " exceeds GL_MAX_3D_TEXTURE_SIZE = " +
                                    std::to_string(gl_limit(GL_MAX_3D_TEXTURE_SIZE)) + " on this GPU");
    // OpenGL ES 3.0 and 3.1 (and so WebGL 2) index an array of samplers only with a constant: the lesson of
    // texture arrays, met head on.
    if (storage == "separate")
        kit.require(gsv::gl_feature::kSamplerArrayIndexing, "storage=separate (slice k is read from uFlowSlices[k])");
    // Unit 0 holds the noise.
    const int free_units = gl_limit(GL_MAX_TEXTURE_IMAGE_UNITS) - 1;
    if (storage == "separate" && slices > free_units)
        throw gsv::UnsupportedError("storage=separate binds one texture unit per slice: slices=" + std::to_string(slices) +
                                    " > the " + std::to_string(free_units) +
                                    " free units (GL_MAX_TEXTURE_IMAGE_UNITS - 1); storage=array needs one");
}

gsv::SweepMetrics measure_sampling(gsv::LabKit& kit, const gsv::ShaderLibrary::Entry& probe, const gsv::GpuMesh& quad,
                                   const gsv::FlowSequence& flow,
                                   const std::function<void(const gsv::ShaderProgram&)>& bind_flow) {
    const auto& p = kit.params();
    const int slices = static_cast<int>(flow.frames.size());
    const gsv::TimeWrap wrap = wrap_of(p);
    const gsv::TimeBlend blend = blend_of(p);

    // What the GPU sampled: one probe fragment per flow texel centre, so no spatial filtering mixes in.
    GLint previous_framebuffer = 0, viewport[4];
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    gsv::Framebuffer target(flow.width, flow.height, gsv::ColorFormat::RGBA32F, false);
    target.bind();
    const gsv::ShaderProgram& program = kit.use(probe);
    bind_flow(program);
    quad.draw();
    const gsv::ImageF sampled = target.read_rgba32f();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previous_framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);

    const double speed = std::max(1e-30, static_cast<double>(flow.max_speed()));
    const gsv::SliceMix now = gsv::slice_mix(p.get_float("time"), kPeriod, slices, wrap, blend);
    double sample_error = 0;
    for (int y = 0; y < flow.height; ++y)
        for (int x = 0; x < flow.width; ++x) {
            const float* got = sampled.at(x, flow.height - 1 - y);  // readback rows run top down
            const glm::dvec2 want = mixed(flow, now, x, y);
            sample_error = std::max({sample_error, std::abs(got[0] - want.x), std::abs(got[1] - want.y)});
        }

    // The temporal error is the CPU's: what T slices can represent, whatever the storage. The playheads
    // (10 j + 3) / 370 of the period never fall on a slice of a power-of-two T: 5 never divides T.
    std::vector<double> times;
    for (int j = 0; j < kErrorTimes; ++j) times.push_back(kPeriod * (j + 0.3) / kErrorTimes);
    const gsv::FlowSequence truth = flow_at_times(kit, times);
    double squared = 0;
    long count = 0;
    for (int j = 0; j < kErrorTimes; ++j) {
        const gsv::SliceMix ours = gsv::slice_mix(times[static_cast<std::size_t>(j)], kPeriod, slices, wrap, blend);
        for (int y = 0; y < flow.height; y += 2)
            for (int x = 0; x < flow.width; x += 2) {
                const glm::dvec2 d = mixed(flow, ours, x, y) - glm::dvec2(truth.frames[static_cast<std::size_t>(j)].at(x, y));
                squared += glm::dot(d, d);
                ++count;
            }
    }
    const double mib = 8.0 * slices * flow.width * flow.height / (1024.0 * 1024.0);
    return {{"sample_err", sample_error / speed},
            {"temporal_rmse", std::sqrt(squared / std::max(1L, count)) / speed},
            {"flow_MiB", mib}};
}

}  // namespace lab03
