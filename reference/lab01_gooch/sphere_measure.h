#pragma once
// Lab 01's sweep measures: what each shading rate lights a pixel with, against the exact sphere lit with its
// exact normal, over the pixels the mesh covers; for its sweep plan (sweep_plan.cpp). Compiled into lab01_solution
// only.
#include "common/app/sweep_plan.h"
#include "common/image/image.h"

namespace lab01 {

// Colour difference in 8-bit levels (largest channel, both colours clamped to [0, 1] as the screen shows them)
// between the mesh's float image and the exact one, over pixels both cover (alpha 1).
gsv::SweepMetrics shading_error(const gsv::ImageF& lit, const gsv::ImageF& exact);

// Mean and largest of the red channel (an angle in degrees) over covered pixels.
gsv::SweepMetrics normal_error(const gsv::ImageF& angles);

}  // namespace lab01
