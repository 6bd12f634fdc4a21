// Lab 05: the particle buffers as the compute stage sees them, one block per binding point (the C++ binds
// them with glBindBufferBase to the same numbers: particle_buffers.h). std430 packs arrays tightly; for
// vec4s it gives the same 16-byte stride as the seed's std140, which would pad a float[] to 16 bytes a
// value.
#pragma once

struct Origin {
    vec4 position;  // where the particle starts, and returns to when it leaves the domain
    vec4 velocity;  // its velocity there
};

layout(std430, binding = 0) buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) buffer Velocities { vec4 velocities[]; };
layout(std430, binding = 2) readonly buffer Origins { Origin origins[]; };
layout(std430, binding = 3) writeonly buffer Colors { vec4 colors[]; };
