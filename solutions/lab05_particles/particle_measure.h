#pragma once
// Lab 05's sweep columns: what a step costs on the GPU and on the CPU, how close the GPU's float steps
// come to the double-precision truth, and how near the GPU runs to the memory's speed limit.
#include "common/app/app.h"
#include "particle_stepper.h"
#include "support/particles/particle_motion.h"

namespace lab05 {

// The buffers hold `steps` steps from `initial` at the current settings; measuring restarts them.
gsv::SweepMetrics measure(gsv::LabKit& kit, const Stepper& stepper, const gsv::ParticleSet& initial, long steps);

}  // namespace lab05
