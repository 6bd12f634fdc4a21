#pragma once
// Lab 05: running the compute shader over the particle buffers, one dispatch per time step.
#include "common/app/app.h"
#include "common/gl/compute.h"
#include "common/gl/texture.h"
#include "particle_buffers.h"

#include <cstdint>

namespace lab05 {

// Slots for `count` particles: whole blocks of 1024, at least one sentinel, and at least every invocation
// the dispatch launches, so an invocation past the count writes into memory that exists (a missing bounds
// check then moves sentinels, which the grader sees, instead of corrupting what a driver owns).
std::size_t capacity_for(std::size_t count, std::uint32_t local_size, const gsv::ComputeLimits& limits);

// round(time / h): the number of steps that shows the simulated time `time`.
long steps_for(double time, double h);

struct Stepper {
    gsv::LabKit& kit;
    const gsv::ShaderLibrary::Entry& advect;
    ParticleBuffers& buffers;
    const gsv::Texture& velocity_texture;  // no texture: the field's formula
    const gsv::ComputeLimits& limits;

    // Back to the starting state, coloured by a step of length 0.
    void restart(const gsv::ParticleSet& initial) const;
    void run(long steps, float h) const;
};

}  // namespace lab05
