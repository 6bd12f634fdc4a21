#include "particle_measure.h"

#include "common/gl/buffer.h"
#include "common/gl/gl.h"
#include "common/timing/timing.h"
#include "support/particles/particle_cpu.h"
#include "support/particles/particle_grid.h"

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

// Median seconds of `work` (bracketed by glFinish, which costs the CPU's work nothing).
double median_seconds(const std::function<void()>& work, int repeats) {
    return gsv::time_frames(work, 0, repeats).median_ms / 1000.0;
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

gsv::SweepMetrics measure(gsv::LabKit& kit, const Stepper& stepper, const gsv::ParticleSet& initial, long steps) {
    const auto& p = kit.params();
    const std::size_t count = stepper.buffers.count;
    const double h = p.get_float("time_step");
    gsv::StepSpec spec{gsv::particle_scene_from_name(p.get_choice("field")), gsv::integrator_from_name(p.get_choice("integrator")),
                       h, p.get_float("gravity")};
    std::optional<gsv::VelocityGrid> grid;
    if (p.get_choice("source") == "texture") grid = gsv::VelocityGrid::sample(spec.scene, p.get_int("grid"));
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
    double sum2 = 0, worst = 0, cpu_gap = 0;
    int followed = 0;
    for (std::size_t k = 0; k < sample.size(); ++k) {
        const glm::dvec3 q(gpu[sample[k]]);
        if (reference.exited[k] || own.exited[k]) continue;
        cpu_gap = std::max(cpu_gap, glm::length(q - glm::dvec3(same.positions[k])));
        const double e = glm::length(q - reference.positions[k]);
        sum2 += e * e;
        worst = std::max(worst, e);
        ++followed;
    }

    // Speed: steps alone on the GPU (no drawing), and the same step on every CPU core.
    const float hf = static_cast<float>(h);
    stepper.restart(initial);
    stepper.run(2, hf);
    glFinish();
    const int batch = 4;
    const double gpu_step_s = median_seconds([&] { stepper.run(batch, hf); }, 5) / batch;
    gsv::ParticleSet cpu_set = initial;
    const double cpu_step_s = median_seconds([&] { gsv::advance_cpu(cpu_set, count, spec, 1); }, 3);
    const double gpu_rate = static_cast<double>(count) / gpu_step_s;
    const double cpu_rate = static_cast<double>(count) / cpu_step_s;
    // Without colours the shader writes 16 bytes a particle fewer.
    const double bytes = gsv::bytes_per_particle_step(spec) - (p.get_bool("color_by_speed") ? 0.0 : 16.0);

    return {{"steps", static_cast<double>(steps)},
            {"gpu_ms_per_step", 1000.0 * gpu_step_s},
            {"gpu_Mparticles_s", gpu_rate / 1e6},
            {"cpu_Mparticles_s", cpu_rate / 1e6},
            {"gpu_over_cpu", gpu_rate / cpu_rate},
            {"gpu_bandwidth_fraction", gpu_rate * bytes / gpu_copy_bandwidth()},
            {"cpu_bandwidth_fraction", cpu_rate * bytes / cpu_copy_bandwidth()},
            {"pos_err_rms", followed ? std::sqrt(sum2 / followed) : 0.0},
            {"pos_err_max", worst},
            {"followed", static_cast<double>(followed)},
            {"gpu_vs_cpu_max", cpu_gap}};
}

}  // namespace lab05
