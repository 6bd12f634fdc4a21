#include "particle_buffers.h"

#include "common/core/error.h"
#include "common/gl/gl.h"

#include <algorithm>
#include <cstddef>

namespace lab05 {

namespace {

// The transform-feedback step's inputs: this step's state, and each particle's origin (two vec4s a particle).
gsv::VertexArrayName step_inputs(const ParticleBuffers& b) {
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    const auto attribute = [](GLuint slot, const gsv::Buffer& buffer, GLsizei stride, std::size_t offset) {
        glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
        glEnableVertexAttribArray(slot);
        glVertexAttribPointer(slot, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
    };
    attribute(gsv::kVertexSlot, b.positions, sizeof(glm::vec4), 0);
    attribute(kStepVelocity, b.velocities, sizeof(glm::vec4), 0);
    attribute(kStepStartPosition, b.origins, sizeof(gsv::ParticleOrigin), offsetof(gsv::ParticleOrigin, position));
    attribute(kStepStartVelocity, b.origins, sizeof(gsv::ParticleOrigin), offsetof(gsv::ParticleOrigin, velocity));
    attribute(kColorSlot, b.colors, sizeof(glm::vec4), 0);
    glBindVertexArray(0);
    return gsv::VertexArrayName(vao);
}

}  // namespace

ParticleBuffers allocate_particle_buffers(std::size_t count, std::size_t capacity, bool compute) {
    ParticleBuffers b;
    b.count = count;
    b.capacity = capacity;
    const std::size_t vec4s = capacity * sizeof(glm::vec4);
    const GLenum target = compute ? GL_SHADER_STORAGE_BUFFER : GL_ARRAY_BUFFER;
    // GL_DYNAMIC_DRAW: written by the GPU every step, read by the GPU to draw.
    b.positions = gsv::Buffer::create(target, vec4s, nullptr, GL_DYNAMIC_DRAW);
    b.velocities = gsv::Buffer::create(target, vec4s, nullptr, GL_DYNAMIC_DRAW);
    b.origins = gsv::Buffer::create(target, capacity * sizeof(gsv::ParticleOrigin), nullptr, GL_STATIC_DRAW);
    b.colors = gsv::Buffer::create(target, vec4s, nullptr, GL_DYNAMIC_DRAW);
    if (!compute) {
        b.next_positions = gsv::Buffer::create(GL_ARRAY_BUFFER, vec4s, nullptr, GL_DYNAMIC_COPY);
        b.next_velocities = gsv::Buffer::create(GL_ARRAY_BUFFER, vec4s, nullptr, GL_DYNAMIC_COPY);
        b.next_colors = gsv::Buffer::create(GL_ARRAY_BUFFER, vec4s, nullptr, GL_DYNAMIC_COPY);
        b.step_inputs = step_inputs(b);
    }

    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    b.points = gsv::VertexArrayName(vao);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, b.positions.id());
    glEnableVertexAttribArray(gsv::kVertexSlot);
    glVertexAttribPointer(gsv::kVertexSlot, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, b.colors.id());
    glEnableVertexAttribArray(kColorSlot);
    glVertexAttribPointer(kColorSlot, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    gsv::check_gl_error("allocating the particle buffers");
    return b;
}

void write_particles(ParticleBuffers& buffers, const gsv::ParticleSet& set) {
    if (set.count() != buffers.capacity)
        throw gsv::Error("write_particles: " + std::to_string(set.count()) + " particles for " +
                         std::to_string(buffers.capacity) + " slots");
    // Invalidating tells the driver the old contents may go: it need not wait for a step still reading them.
    glm::vec4* positions = buffers.positions.map_write_invalidate_as<glm::vec4>();
    std::copy(set.positions.begin(), set.positions.end(), positions);
    buffers.positions.unmap();
    // TODO(L05-T1): the velocities and the origins the same way (the origins are ParticleOrigin structs,
    // laid out as particles.glsl's Origin). The colours are the shader's to write.
//@solution L05-T1
    glm::vec4* velocities = buffers.velocities.map_write_invalidate_as<glm::vec4>();
    std::copy(set.velocities.begin(), set.velocities.end(), velocities);
    buffers.velocities.unmap();
    gsv::ParticleOrigin* origins = buffers.origins.map_write_invalidate_as<gsv::ParticleOrigin>();
    std::copy(set.origins.begin(), set.origins.end(), origins);
    buffers.origins.unmap();
//@starter
//    // Until then, zeros, so the starter behaves the same on every GPU (allocated buffers hold anything).
//    const std::vector<glm::vec4> zeros(2 * set.count());
//    buffers.velocities.upload(0, buffers.velocities.size(), zeros.data());
//    buffers.origins.upload(0, buffers.origins.size(), zeros.data());
//@end
    gsv::check_gl_error("writing the particles");
}

void bind_particle_buffers(const ParticleBuffers& buffers) {
    buffers.positions.bind_base(kPositions);
    buffers.velocities.bind_base(kVelocities);
    buffers.origins.bind_base(kOrigins);
    buffers.colors.bind_base(kColors);
}

void draw_particles(const ParticleBuffers& buffers) {
    glBindVertexArray(buffers.points.get());
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(buffers.count));
    glBindVertexArray(0);
}

std::vector<glm::vec4> read_vec4s(gsv::Buffer& buffer, std::size_t slots) {
    if (glMemoryBarrier) glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // none below ES 3.1: transform feedback needs none
    const glm::vec4* data = buffer.map_read_as<glm::vec4>();
    std::vector<glm::vec4> out(data, data + std::min(slots, buffer.size() / sizeof(glm::vec4)));
    buffer.unmap();
    return out;
}

}  // namespace lab05
