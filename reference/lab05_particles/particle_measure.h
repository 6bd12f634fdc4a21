#pragma once
// Lab 05's sweep columns, the instructor's: what a step costs on the GPU and on the CPU (the CPU running the same
// integrators, reference/particles/), how close the GPU's float steps come to the double-precision truth, and how
// near the GPU runs to the memory's speed limit. Compiled into lab05_solution only; the student's sweep has the
// images and frame times alone.
#include "common/app/app.h"
#include "particle_stepper.h"
#include "reference/particles/particle_step.h"

namespace lab05 {

// The buffers hold `steps` steps from `initial` at the current settings; measuring restarts them.
gsv::SweepMetrics measure(const Stepper& stepper, const gsv::ParticleSet& initial, long steps);

}  // namespace lab05
