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

double storage_bytes_per_particle_step(bool gravity, bool colored) {
    const double reads = 16 + (gravity ? 16 : 0);
    const double writes = 16 + 16 + (colored ? 16 : 0);
    return reads + writes;
}

void Stepper::restart(const gsv::ParticleSet& initial) const {
    write_particles(buffers, initial);
    // Velocities and colours as the shader sees them at the start: a step of length 0 moves nothing.
    if (kit.allows(gsv::gl_feature::kCompute)) glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    run(1, 0.0f);
}

void Stepper::run(long steps, float h) const {
    if (steps <= 0) return;
    const gsv::ShaderProgram& program = kit.use(advect);
    program.set("uTimeStep", h);
    if (velocity_texture.id()) program.bind("uVelocityTexture", velocity_texture);
    if (!kit.allows(gsv::gl_feature::kCompute)) return run_captured(steps);
    program.set("uCount", static_cast<int>(buffers.count));
    bind_particle_buffers(buffers);
    const auto local = static_cast<std::uint32_t>(params.local_size.get());
    for (long i = 0; i < steps; ++i) {
        gsv::dispatch_items(buffers.count, local, limits);
        // The next step reads what this one wrote.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
}

// Every particle is a point drawn with nothing rasterised; its new position, velocity and colour are captured into the
// next buffers and copied back, so the buffers drawn (and read back) are the same as the compute step's.
void Stepper::run_captured(long steps) const {
    const auto count = static_cast<GLsizei>(buffers.count);
    // The particles only: the sentinel slots beyond them stay as written, as the compute step leaves them.
    const auto bytes = static_cast<GLsizeiptr>(buffers.count * sizeof(glm::vec4));
    const gsv::Buffer* captured[] = {&buffers.next_positions, &buffers.next_velocities, &buffers.next_colors};
    const gsv::Buffer* state[] = {&buffers.positions, &buffers.velocities, &buffers.colors};
    // WebGL refuses to capture into a buffer bound anywhere else (the array and copy targets included).
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glEnable(GL_RASTERIZER_DISCARD);
    glBindVertexArray(buffers.step_inputs.get());
    for (long i = 0; i < steps; ++i) {
        for (GLuint k = 0; k < 3; ++k) glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, k, captured[k]->id());
        glBeginTransformFeedback(GL_POINTS);
        glDrawArrays(GL_POINTS, 0, count);
        glEndTransformFeedback();
        for (GLuint k = 0; k < 3; ++k) glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, k, 0);
        for (int k = 0; k < 3; ++k) {
            glBindBuffer(GL_COPY_READ_BUFFER, captured[k]->id());
            glBindBuffer(GL_COPY_WRITE_BUFFER, state[k]->id());
            glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, bytes);
        }
        glBindBuffer(GL_COPY_READ_BUFFER, 0);
        glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    }
    glBindVertexArray(0);
    glDisable(GL_RASTERIZER_DISCARD);
    gsv::check_gl_error("stepping the particles by transform feedback");
}

}  // namespace lab05
