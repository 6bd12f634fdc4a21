#pragma once
// Lab 06's sweep columns with compare_shaders=on: what the same image costs through the uber-shader and the
// hand-written DVR, for its sweep plan (sweep_plan.cpp). Compiled into lab06_solution only.
#include "common/app/sweep_plan.h"
#include "ray_traversal.h"

namespace lab06 {

// The ray caster alone, timed (glFinish and a steady clock, median of 5 after 1 warm-up) with each shader
// at the current configuration: specialised_ms, uber_ms and uber_over_specialised, and for DVR with
// central gradients, a transfer function and Phong also handwritten_ms and specialised_over_handwritten.
// The inputs are those of the network's last run.
gsv::SweepMetrics compare_shaders(RayTraversal& raycaster);

}  // namespace lab06
