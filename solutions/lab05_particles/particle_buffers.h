#pragma once
// Lab 05: the particles in shader storage buffers, bound to the indexed points particles.glsl declares,
// and the same buffers bound as vertex arrays to draw them: the positions never travel back to the CPU.
#include "common/gl/buffer.h"
#include "common/gl/gl_object.h"
#include "common/shader/shader_program.h"
#include "support/particles/particle_motion.h"

#include <cstddef>
#include <vector>

namespace lab05 {

// The binding points of particles.glsl's buffer blocks.
enum Binding : GLuint { kPositions = 0, kVelocities = 1, kOrigins = 2, kColors = 3 };
// The colours' vertex attribute (particles.vert); positions use the kit's aVertex slot.
inline constexpr GLuint kColorSlot = 3;
// Where there are no compute shaders: the attribute slots of the transform-feedback step (advect_captured.vert): the
// position in the kit's aVertex slot and the colour in aColor's, as when the particles are drawn; the rest clear of
// the kit's aNormal and aTexCoord0.
enum StepSlot : GLuint { kStepVelocity = 4, kStepStartPosition = 5, kStepStartVelocity = 6 };

struct ParticleBuffers {
    gsv::Buffer positions, velocities, origins, colors;
    gsv::VertexArrayName points;  // positions as aVertex, colours as aColor
    std::size_t count = 0;        // particles drawn and moved
    std::size_t capacity = 0;     // slots: the rest hold sentinels that nothing may touch
    // Transform feedback only (no compute shaders): a step reads the buffers above as vertex attributes and writes
    // these, which are then copied back (a buffer cannot be read and captured into at once).
    gsv::Buffer next_positions, next_velocities, next_colors;
    gsv::VertexArrayName step_inputs;
};

// Buffers for `capacity` particles, allocated with no data: the GPU owns them from here on. `compute`: storage buffers
// for the compute step; otherwise vertex buffers and the second set the transform-feedback step writes.
ParticleBuffers allocate_particle_buffers(std::size_t count, std::size_t capacity, bool compute);
// The starting state, written the seed's way (map, invalidate, write, unmap); `set` holds capacity slots.
void write_particles(ParticleBuffers& buffers, const gsv::ParticleSet& set);
void bind_particle_buffers(const ParticleBuffers& buffers);
void draw_particles(const ParticleBuffers& buffers);
// Element-major copies of the first `slots` slots of a buffer of vec4s (after the last dispatch's writes).
std::vector<glm::vec4> read_vec4s(gsv::Buffer& buffer, std::size_t slots);

}  // namespace lab05
