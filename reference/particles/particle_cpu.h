#pragma once
// Lab 05's two CPU yardsticks for its compute shader: a multi-threaded float update (how fast the CPU does
// the same work, and what the GPU's numbers should be to a few ulps) and a double-precision reference from
// the initial state (what the numbers should be, to measure the integrators' error). Plus the memory
// bandwidth and per-particle traffic that put a measured speed against the bound memory sets.
#include "reference/particles/particle_step.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace gsv {

// `steps` float steps of step_particle on the first `count` particles of `set`, in place; the slots past
// `count` (pad_particles' sentinels) are not touched, and the w components are kept. `threads` workers
// (0: std::thread::hardware_concurrency, at most one per particle) each own one contiguous chunk and run all
// the steps on it, particle after particle: particles are independent, so no barrier between steps is
// needed and the result is bit-identical for every thread count. Throws gsv::Error for count above the
// set's size, arrays of different sizes, steps or threads below 0, or a spec check_step_spec refuses.
void advance_cpu(ParticleSet& set, std::size_t count, const StepSpec& spec, int steps, int threads = 0);

struct ReferenceRun {
    std::vector<glm::dvec3> positions;  // one per index asked for, in that order
    std::vector<bool> exited;           // the particle left the domain (and restarted) at least once
};

// The particles indices[m] of `set`, as make_particles started them (positions and velocities; pass the
// untouched initial set, not one already advanced), advanced `steps` steps of spec.h in double, each step as
// `substeps` steps of h / substeps with spec.integrator (and the domain test after each of them), restarting
// at their origins when they leave. substeps = 1 is the
// same method as the float run in double; rk4 with many substeps converges to the exact path (for the
// scenes' smooth fields). Throws gsv::Error for an index past the set, steps < 0, substeps < 1, or a spec
// check_step_spec refuses.
ReferenceRun advance_reference(const ParticleSet& set, const std::vector<std::size_t>& indices, const StepSpec& spec,
                               int steps, int substeps);

// Indices spread evenly over 0 .. count-1, floor(m count / at_most) for m = 0 .. at_most-1: all of them
// when count <= at_most, none when at_most = 0. In increasing order, no repeats.
std::vector<std::size_t> reference_sample(std::size_t count, std::size_t at_most);

// Memory bandwidth in bytes per second as std::memcpy of `bytes` between two buffers sees it: each copy
// counts 2 * bytes (bytes read plus bytes written), over the fastest of `repeats` copies (steady_clock),
// after both buffers were written once so no page fault is timed. Choose `bytes` well above the last-level
// cache (the default 256 MiB is; two buffers are allocated). Caveat: a copy that does not use streaming
// stores also reads each destination line before writing it (write-allocate), traffic not counted here,
// so this can read low by up to a third of the true DRAM rate; glibc's memcpy streams copies this large.
// Throws gsv::Error for bytes = 0 or repeats < 1.
double measure_copy_bandwidth(std::size_t bytes = std::size_t(256) << 20, int repeats = 5);

// The compute shader's memory traffic per particle per step, in bytes: a field scene reads the position
// (16) and writes position, velocity and colour (48), 64 in all; gravity also reads the velocity, 80. Not
// counted: the origins (read only when a particle restarts), and the field texture (a few KiB to MiB,
// mostly served from the texture cache). So (particles * steps * this) / seconds, over the bandwidth of the
// memory the kernel reads (the GPU's, for the shader), is the fraction of the memory-bandwidth bound it
// reaches, for a kernel that does one step per dispatch. advance_cpu is not such a kernel: it keeps a
// particle in registers for all its steps and touches memory once per run, so its speed is bound by
// arithmetic, not by this traffic.
double bytes_per_particle_step(const StepSpec& spec);

}  // namespace gsv
