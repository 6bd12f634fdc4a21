#include "time_measure.h"

#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "reference/flow/time_slices.h"
#include "time_flow.h"

#include <algorithm>
#include <cmath>

namespace lab03 {
namespace {

constexpr int kErrorTimes = 37;  // playheads over the period for the temporal error (prime)

// The flow of `sequence` at the playhead as the shader should sample it, at texel (x, y).
glm::dvec2 mixed(const gsv::FlowSequence& sequence, const gsv::SliceMix& m, int x, int y) {
    const glm::dvec2 a(sequence.frames[static_cast<std::size_t>(m.first)].at(x, y));
    const glm::dvec2 b(sequence.frames[static_cast<std::size_t>(m.second)].at(x, y));
    return a + m.weight * (b - a);
}

// The flow itself at each of `times`, as the observer sees it: an analytic flow sampled there, or a file's frames,
// spread over the period like slices, blended linearly in time.
gsv::FlowSequence true_flow_at_times(const gsv::LabKit& kit, const SliceParams& p, const std::vector<double>& times) {
    if (p.field.get() != Field::File) return seen_by_observer(p, analytic_flow_at_times(p, times));
    const FileFlow file = load_file_flow(kit, p);
    gsv::FlowSequence out;
    out.width = file.frames.width;
    out.height = file.frames.height;
    for (double time : times) {
        const gsv::SliceMix m = gsv::slice_mix(time, kPeriod, static_cast<int>(file.frames.frames.size()), p.time_wrap.get(),
                                               gsv::TimeBlend::Linear);
        gsv::FlowField frame = file.frames.frames[static_cast<std::size_t>(m.first)];
        for (int y = 0; y < frame.height; ++y)
            for (int x = 0; x < frame.width; ++x) {
                const glm::dvec2 v = mixed(file.frames, m, x, y) * file.scale;
                const std::size_t i = 2 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(x));
                frame.velocity[i] = static_cast<float>(v.x);
                frame.velocity[i + 1] = static_cast<float>(v.y);
            }
        out.frames.push_back(std::move(frame));
    }
    return seen_by_observer(p, std::move(out));
}

}  // namespace

gsv::SweepMetrics measure_sampling(gsv::LabKit& kit, const SliceParams& p, const gsv::ShaderLibrary::Entry& probe,
                                   const gsv::GpuMesh& quad, const gsv::FlowSequence& flow,
                                   const std::function<void(const gsv::ShaderProgram&)>& bind_flow) {
    const int slices = static_cast<int>(flow.frames.size());
    const gsv::TimeWrap wrap = p.time_wrap.get();
    const gsv::TimeBlend blend = p.blend.get();

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
    const gsv::SliceMix now = gsv::slice_mix(p.time.get(), kPeriod, slices, wrap, blend);
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
    const gsv::FlowSequence truth = true_flow_at_times(kit, p, times);
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
