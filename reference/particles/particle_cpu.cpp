// The multi-threaded float particle update, the double-precision reference, and the bandwidth yardstick.
#include "reference/particles/particle_cpu.h"

#include "common/core/error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <thread>

namespace gsv {
namespace {

void check_sizes(const char* who, const ParticleSet& set) {
    if (set.velocities.size() != set.count() || set.origins.size() != set.count())
        throw Error(std::string(who) + ": " + std::to_string(set.count()) + " positions but " +
                    std::to_string(set.velocities.size()) + " velocities and " + std::to_string(set.origins.size()) +
                    " origins");
}

// Particles [begin, end) of `set`, all `steps` steps each; w components kept.
void advance_chunk(ParticleSet& set, std::size_t begin, std::size_t end, const StepSpec& spec, int steps) {
    for (std::size_t i = begin; i < end; ++i) {
        glm::vec3 p(set.positions[i]), v(set.velocities[i]);
        const glm::vec3 p0(set.origins[i].position), v0(set.origins[i].velocity);
        for (int s = 0; s < steps; ++s) step_particle<float>(spec, p, v, p0, v0);
        set.positions[i] = glm::vec4(p, set.positions[i].w);
        set.velocities[i] = glm::vec4(v, set.velocities[i].w);
    }
}

}  // namespace

void advance_cpu(ParticleSet& set, std::size_t count, const StepSpec& spec, int steps, int threads) {
    check_sizes("advance_cpu", set);
    if (count > set.count())
        throw Error("advance_cpu: count " + std::to_string(count) + " is above the set's " +
                    std::to_string(set.count()) + " particles");
    if (steps < 0) throw Error("advance_cpu: steps = " + std::to_string(steps) + " must be >= 0");
    if (threads < 0) throw Error("advance_cpu: threads = " + std::to_string(threads) + " must be >= 0");
    check_step_spec(spec);

    std::size_t workers = threads > 0 ? static_cast<std::size_t>(threads) : std::thread::hardware_concurrency();
    workers = std::max<std::size_t>(1, std::min(workers, count));
    // Chunk t is [count t / workers, count (t+1) / workers): sizes differ by at most one. The caller's
    // thread takes the last chunk instead of waiting idle.
    const auto chunk_start = [&](std::size_t t) { return count / workers * t + count % workers * t / workers; };
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    try {
        for (std::size_t t = 0; t + 1 < workers; ++t)
            pool.emplace_back(advance_chunk, std::ref(set), chunk_start(t), chunk_start(t + 1), std::cref(spec), steps);
    } catch (...) {
        // A thread that could not be started: let those that did finish before the set goes away.
        for (std::thread& worker : pool) worker.join();
        throw;
    }
    advance_chunk(set, chunk_start(workers - 1), count, spec, steps);
    for (std::thread& worker : pool) worker.join();
}

ReferenceRun advance_reference(const ParticleSet& set, const std::vector<std::size_t>& indices, const StepSpec& spec,
                               int steps, int substeps) {
    check_sizes("advance_reference", set);
    if (steps < 0) throw Error("advance_reference: steps = " + std::to_string(steps) + " must be >= 0");
    if (substeps < 1) throw Error("advance_reference: substeps = " + std::to_string(substeps) + " must be >= 1");
    check_step_spec(spec);
    for (std::size_t index : indices)
        if (index >= set.count())
            throw Error("advance_reference: index " + std::to_string(index) + " is past the set's " +
                        std::to_string(set.count()) + " particles");

    StepSpec sub = spec;
    sub.h = spec.h / substeps;
    ReferenceRun run;
    run.positions.reserve(indices.size());
    run.exited.reserve(indices.size());
    for (std::size_t index : indices) {
        const glm::dvec3 p0(set.origins[index].position), v0(set.origins[index].velocity);
        glm::dvec3 p(set.positions[index]), v(set.velocities[index]);
        bool exited = false;
        for (long long s = 0, total = static_cast<long long>(steps) * substeps; s < total; ++s)
            exited = step_particle<double>(sub, p, v, p0, v0) || exited;
        run.positions.push_back(p);
        run.exited.push_back(exited);
    }
    return run;
}

std::vector<std::size_t> reference_sample(std::size_t count, std::size_t at_most) {
    std::vector<std::size_t> indices;
    if (count <= at_most) {
        indices.resize(count);
        for (std::size_t i = 0; i < count; ++i) indices[i] = i;
        return indices;
    }
    // floor(m count / at_most) without forming m * count, which could overflow: count = q at_most + r.
    const std::size_t q = count / at_most, r = count % at_most;
    indices.resize(at_most);
    for (std::size_t m = 0; m < at_most; ++m) indices[m] = m * q + m * r / at_most;
    return indices;
}

double measure_copy_bandwidth(std::size_t bytes, int repeats) {
    if (bytes == 0) throw Error("measure_copy_bandwidth: bytes must be positive");
    if (repeats < 1) throw Error("measure_copy_bandwidth: repeats = " + std::to_string(repeats) + " must be >= 1");
    // Written once each so that the pages exist before anything is timed.
    std::vector<unsigned char> a(bytes, 1), b(bytes, 2);
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r < repeats; ++r) {
        // Back and forth: each copy's destination is the next one's source, so none is dead code.
        unsigned char* to = r % 2 ? a.data() : b.data();
        const unsigned char* from = r % 2 ? b.data() : a.data();
        const auto start = std::chrono::steady_clock::now();
        std::memcpy(to, from, bytes);
        const auto stop = std::chrono::steady_clock::now();
        best = std::min(best, std::chrono::duration<double>(stop - start).count());
    }
    volatile unsigned char sink = a[bytes / 2] ^ b[bytes - 1];
    (void)sink;
    // A copy too small for the clock to see is reported at the clock's resolution rather than as infinite.
    const double resolution =
        std::chrono::duration<double>(std::chrono::steady_clock::duration(1)).count();
    return 2.0 * static_cast<double>(bytes) / std::max(best, resolution);
}

double bytes_per_particle_step(const StepSpec& spec) {
    constexpr double kVec4 = 16;
    const double reads = spec.scene == ParticleScene::Gravity ? 2 * kVec4 : kVec4;  // position (and velocity)
    const double writes = 3 * kVec4;                                                // position, velocity, colour
    return reads + writes;
}

}  // namespace gsv
