#include "particle_stepper.h"

#include "common/gl/gl.h"

#include <algorithm>
#include <cmath>

namespace lab05 {

std::size_t capacity_for(std::size_t count, std::uint32_t local_size, const gsv::ComputeLimits& limits) {
    const std::uint64_t launched = gsv::dispatch_grid(count, local_size, limits).invocations(local_size);
    const std::uint64_t slots = std::max<std::uint64_t>(count + 1, launched);
    return static_cast<std::size_t>((slots + 1023) / 1024 * 1024);
}

long steps_for(double time, double h) { return h > 0 ? std::lround(time / h) : 0; }

void Stepper::restart(const gsv::ParticleSet& initial) const {
    write_particles(buffers, initial);
    // Velocities and colours as the shader sees them at the start: a step of length 0 moves nothing.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    run(1, 0.0f);
}

void Stepper::run(long steps, float h) const {
    if (steps <= 0) return;
    const gsv::ShaderProgram& program = kit.use(advect);
    program.set("uCount", static_cast<int>(buffers.count));
    program.set("uTimeStep", h);
    if (velocity_texture.id()) program.bind("uVelocityTexture", velocity_texture);
    bind_particle_buffers(buffers);
    const auto local = static_cast<std::uint32_t>(kit.params().get_int("local_size"));
    for (long i = 0; i < steps; ++i) {
        gsv::dispatch_items(buffers.count, local, limits);
        // The next step reads what this one wrote.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
}

}  // namespace lab05
