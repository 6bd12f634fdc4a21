#pragma once
// Lab 05: running the compute shader over the particle buffers, one dispatch per time step; where there are no compute
// shaders (WebGL 2, OpenGL ES 3.0), the same step as a draw of points whose outputs transform feedback captures.
#include "common/app/app.h"
#include "common/gl/compute.h"
#include "common/gl/texture.h"
#include "particle_buffers.h"
#include "support/particles/particle_motion.h"

#include <cstdint>

namespace lab05 {

// Slots for `count` particles: whole blocks of 1024, at least one sentinel, and at least every invocation
// the dispatch launches, so an invocation past the count writes into memory that exists (a missing bounds
// check then moves sentinels, which the grader sees, instead of corrupting what a driver owns).
std::size_t capacity_for(std::size_t count, std::uint32_t local_size, const gsv::ComputeLimits& limits);

// round(time / h): the number of steps that shows the simulated time `time`.
long steps_for(double time, double h);

// The bytes one step must move through the storage buffers for each particle, as advect.comp uses them: it reads the
// position (16 bytes) and, under gravity, the velocity (a velocity field computes its own: the shader's load of it is
// dead there, and compilers drop it), and writes the position, the velocity and, coloured by speed, the colour (16
// each). The origin (32 bytes, returnIfOutside's) is read only by a particle that leaves the domain: not counted. So
// this is the least a step moves, never more: a step measured faster than these bytes allow at the device's storage
// ceiling did not wait for the device (gsv::check_within_ceiling), and its share of the bandwidth is at least this.
// The lab's statement of its work (frame_work), which the instructor's sweep also divides by the storage bandwidth.
double storage_bytes_per_particle_step(bool gravity, bool colored);

// Where the shader finds the field: its formula, or its samples in a 3D texture.
enum class Source { Analytic, Texture };
inline constexpr gsv::EnumName<Source> kSources[] = {{Source::Analytic, "analytic"}, {Source::Texture, "texture"}};

// The lab's parameters a step and its measurement read: declared by the lab (lab.cpp), which keeps them.
struct ParticleParams {
    gsv::EnumParam<gsv::ParticleScene> field;
    gsv::EnumParam<Source> source;
    gsv::Param<int> grid;
    gsv::EnumParam<gsv::Integrator> integrator;
    gsv::Param<float> time_step;
    gsv::Param<int> local_size;
    gsv::Param<float> gravity;
    gsv::Param<bool> color_by_speed;
};

struct Stepper {
    gsv::LabKit& kit;
    const ParticleParams& params;
    const gsv::ShaderLibrary::Entry& advect;
    ParticleBuffers& buffers;
    const gsv::Texture& velocity_texture;  // no texture: the field's formula
    const gsv::ComputeLimits& limits;

    // Back to the starting state, coloured by a step of length 0.
    void restart(const gsv::ParticleSet& initial) const;
    void run(long steps, float h) const;

private:
    void run_captured(long steps) const;  // the transform-feedback step, for a program already in use
};

}  // namespace lab05
