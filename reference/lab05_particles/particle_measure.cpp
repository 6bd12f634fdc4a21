#include "particle_measure.h"

#include "common/app/sweep_metrics.h"
#include "common/gl/buffer.h"
#include "common/gl/gl.h"
#include "common/timing/timing.h"
#include "reference/particles/particle_cpu.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace lab05 {
namespace {

// The converged reference: RK4 in double with substeps no longer than this.
constexpr double kReferenceStep = 1e-3;
// Particles followed in double precision; more would make the reference the slow part of a sweep.
constexpr std::size_t kReferenceParticles = 2048;

gsv::ParticleSet subset(const gsv::ParticleSet& all, const std::vector<std::size_t>& indices) {
    gsv::ParticleSet out;
    for (std::size_t i : indices) {
        out.positions.push_back(all.positions[i]);
        out.velocities.push_back(all.velocities[i]);
        out.origins.push_back(all.origins[i]);
    }
    return out;
}

// Bytes per second a buffer-to-buffer copy moves on this GPU (read and write counted): the speed limit of a
// step that does little arithmetic per byte. On llvmpipe it is a memcpy in the CPU's memory.
double gpu_copy_bandwidth() {
    static const double bytes_per_second = [] {
        const std::size_t bytes = std::size_t(256) << 20;
        gsv::Buffer from = gsv::Buffer::create(GL_COPY_READ_BUFFER, bytes, nullptr, GL_STATIC_COPY);
        gsv::Buffer to = gsv::Buffer::create(GL_COPY_WRITE_BUFFER, bytes, nullptr, GL_STATIC_COPY);
        glBindBuffer(GL_COPY_READ_BUFFER, from.id());
        glBindBuffer(GL_COPY_WRITE_BUFFER, to.id());
        auto copy = [&] {
            glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, static_cast<GLsizeiptr>(bytes));
        };
        return 2.0 * static_cast<double>(bytes) / gsv::time_frames(copy, 1, 5).median_ms * 1000.0;
    }();
    return bytes_per_second;
}

double cpu_copy_bandwidth() {
    static const double bytes_per_second = gsv::measure_copy_bandwidth();
    return bytes_per_second;
}

}  // namespace

gsv::SweepMetrics measure(const Stepper& stepper, const gsv::ParticleSet& initial, long steps) {
    const ParticleParams& p = stepper.params;
    const std::size_t count = stepper.buffers.count;
    const double h = p.time_step.get();
    gsv::StepSpec spec{p.field.get(), p.integrator.get(), h, p.gravity.get()};
    std::optional<gsv::VelocityGrid> grid;
    if (p.source.get() == Source::Texture) grid = gsv::VelocityGrid::sample(spec.scene, p.grid.get());
    spec.grid = grid ? &*grid : nullptr;

    // Accuracy: the GPU's particles against the same particles in double precision, integrated by RK4 in
    // small substeps through the field's formula (the texture's samples are part of the error).
    const std::vector<std::size_t> sample = gsv::reference_sample(count, kReferenceParticles);
    const std::vector<glm::vec4> gpu = read_vec4s(stepper.buffers.positions, count);
    gsv::StepSpec truth = spec;
    truth.integrator = gsv::Integrator::Rk4;
    truth.grid = nullptr;
    const int substeps = std::max(1, static_cast<int>(std::ceil(h / kReferenceStep)));
    const gsv::ReferenceRun reference = gsv::advance_reference(initial, sample, truth, static_cast<int>(steps), substeps);
    // A particle that left the domain in either run restarted at a time that depends on the step: its
    // distance from the reference says nothing about the integrator. The method's own exits, in double:
    const gsv::ReferenceRun own = gsv::advance_reference(initial, sample, spec, static_cast<int>(steps), 1);
    // Correctness: the same update on the CPU in float.
    gsv::ParticleSet same = subset(initial, sample);
    gsv::advance_cpu(same, same.count(), spec, static_cast<int>(steps));
    double sum2 = 0, worst = 0, cpu_gap = 0, radius_ratio = 0;
    int followed = 0;
    for (std::size_t k = 0; k < sample.size(); ++k) {
        const glm::dvec3 q(gpu[sample[k]]);
        if (reference.exited[k] || own.exited[k]) continue;
        cpu_gap = std::max(cpu_gap, glm::length(q - glm::dvec3(same.positions[k])));
        const double e = glm::length(q - reference.positions[k]);
        sum2 += e * e;
        worst = std::max(worst, e);
        const glm::dvec2 start(glm::dvec3(initial.positions[sample[k]]));
        if (glm::length(start) > 1e-3) radius_ratio += glm::length(glm::dvec2(q)) / glm::length(start);
        ++followed;
    }

    // Speed: steps alone on the GPU (no drawing), and the same step on every CPU core, timed in turns.
    const float hf = static_cast<float>(h);
    stepper.restart(initial);
    gsv::ParticleSet cpu_set = initial;
    const gsv::InterleavedTimes times = gsv::time_interleaved(
        {{nullptr, [&] { stepper.run(1, hf); }}, {nullptr, [&] { gsv::advance_cpu(cpu_set, count, spec, 1); }}}, 1, 2, 3);
    const double gpu_rate = static_cast<double>(count) / (times.stats[0].median_ms / 1000.0);
    const double cpu_rate = static_cast<double>(count) / (times.stats[1].median_ms / 1000.0);
    // The bytes a step moves: the GPU's as the lab states them (its frame work's: the least a step must move), the
    // CPU's as the CPU's update moves them (the same accounting, kept by the instructor's CPU code). Without colours
    // each writes 16 a particle fewer.
    const double gpu_bytes =
        storage_bytes_per_particle_step(spec.scene == gsv::ParticleScene::Gravity, p.color_by_speed.get());
    const double cpu_bytes = gsv::bytes_per_particle_step(spec) - (p.color_by_speed.get() ? 0.0 : 16.0);

    gsv::SweepMetrics m{{"steps", static_cast<double>(steps)}};
    gsv::add_time(m, "gpu_ms_per_step", times.stats[0]);
    m.emplace_back("gpu_Mparticles_s", gpu_rate / 1e6);
    m.emplace_back("cpu_Mparticles_s", cpu_rate / 1e6);
    gsv::add_ratio(m, "gpu_over_cpu", times.ratio(1, 0));
    // scripts/workgroups.py divides the GPU's by the storage ceiling gsv-ceilings measured: the bytes come with it.
    m.emplace_back("bytes_per_particle_step", gpu_bytes);
    m.emplace_back("gpu_bandwidth_fraction", gpu_rate * gpu_bytes / gpu_copy_bandwidth());
    m.emplace_back("cpu_bandwidth_fraction", cpu_rate * cpu_bytes / cpu_copy_bandwidth());
    m.emplace_back("pos_err_rms", followed ? std::sqrt(sum2 / followed) : 0.0);
    m.emplace_back("pos_err_max", worst);
    m.emplace_back("followed", static_cast<double>(followed));
    // The image is drawn from every particle, and one that left the domain restarted from its origin at a step
    // that depends on h: where it is says nothing about accuracy, but it changes the image.
    m.emplace_back("left_share", sample.empty() ? 0.0 : 1.0 - static_cast<double>(followed) / static_cast<double>(sample.size()));
    m.emplace_back("gpu_vs_cpu_max", cpu_gap);
    if (spec.scene == gsv::ParticleScene::Rotation && followed > 0) {
        // The exact flow keeps every radius; each method's closed form says what its steps make of it.
        m.emplace_back("radius_ratio", radius_ratio / followed);
        m.emplace_back("radius_ratio_closed_form", std::pow(gsv::rotation_radius_growth_per_step(spec.integrator, h), steps));
    }
    return m;
}

}  // namespace lab05
