#pragma once
// Which stored time slices make up the flow at a playhead, in double precision: the CPU reference of
// lab 03's sliceCoordinate / nearestSlice / nextSlice (solutions/lab03_texture_arrays/flow_time.glsl).
// T slices cover one period; slice k was sampled at time k * period / T. In reference/, the instructor's: linked by
// the solutions and the tests, never by a student's build.
#include "support/flow/flow_field.h"  // TimeWrap, TimeBlend

namespace gsv {

struct SliceMix {
    int first = 0, second = 0;  // slice indices in [0, T)
    double weight = 0;          // of `second`: flow = (1 - weight) * first + weight * second
};

// Throws gsv::Error unless slices >= 1, period > 0 and time are finite.
double slice_coordinate(double time, double period, int slices, TimeWrap wrap);
SliceMix slice_mix(double time, double period, int slices, TimeWrap wrap, TimeBlend blend);

}  // namespace gsv
