#pragma once
// The CPU's emulation of lab 05's velocity lookup in its 3D texture (L05-T5: GL_LINEAR, GL_CLAMP_TO_EDGE at
// texture coordinate (p + 1) / 2), so that an integration through the grid can be checked on the CPU like one
// through the formula. The instructor's yardstick: students write the lookup in velocity.glsl.
//
// The emulation is the filter as the GL specification states it (section 8.14.2 of GL 4.6) with exact
// weights. Real hardware rounds the weights to a few fractional bits (8 on NVIDIA, per the CUDA
// programming guide's texture fetching appendix), so a GPU lookup can differ from this one by up to about
// 1/512 of the difference between neighbouring texels; compare GPU results against it with that in mind.
#include "support/particles/particle_grid.h"

#include <glm/glm.hpp>

namespace gsv {

// What GL_LINEAR with GL_CLAMP_TO_EDGE returns at texture coordinate s = (p + 1) / 2: per axis
// x = s n - 1/2, i0 = floor(x), f = x - i0, texels i0 and i0 + 1 each clamped to 0 .. n-1, then the
// trilinear mix. So a texel centre gives that texel, and the outer half texel (and anything beyond
// D) gives the edge value. The double version computes in double from the float texels; the float one
// computes each step in float, as the float CPU run does. A NaN coordinate gives NaN.
glm::dvec3 grid_lookup(const VelocityGrid& grid, glm::dvec3 p);
glm::vec3 grid_lookup(const VelocityGrid& grid, glm::vec3 p);

}  // namespace gsv
