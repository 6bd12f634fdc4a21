#pragma once
// The CPU's emulation of lab 05's velocity lookup in its 3D texture (L05-T5: GL_LINEAR, GL_CLAMP_TO_EDGE at
// texture coordinate (p + 1) / 2), so that an integration through the grid can be checked on the CPU like one
// through the formula. The instructor's yardstick: students write the lookup in velocity.glsl.
//
// The emulation is the filter as the GL specification states it (section 8.14.2 of GL 4.6) with exact
// weights, or with the weights a GPU's texture unit uses: real hardware rounds them to a few fractional bits
// (8 on NVIDIA, per the CUDA programming guide's texture fetching appendix; measured on an H200, issue 28's
// stand-in), so its lookup can differ from the exact one by up to about 1/512 of the difference between
// neighbouring texels, and many steps through a grid carry that difference on.
#include "support/particles/particle_grid.h"

#include <glm/glm.hpp>

namespace gsv {

// What GL_LINEAR with GL_CLAMP_TO_EDGE returns at texture coordinate s = (p + 1) / 2: per axis
// x = s n - 1/2, i0 = floor(x), f = x - i0, texels i0 and i0 + 1 each clamped to 0 .. n-1, then the
// trilinear mix. So a texel centre gives that texel, and the outer half texel (and anything beyond
// D) gives the edge value. The double version computes in double from the float texels; the float one
// computes each step in float, as the float CPU run does. A NaN coordinate gives NaN.
// `weight_steps` N > 0: x rounded to the nearest 1/N of a texel first, so each weight takes only N + 1 values, as on
// a GPU with log2(N) fractional bits (GSV_TEXEL_SNAP's rounding, shaders/gsv/texel_snap.glsl); 0: exact weights.
glm::dvec3 grid_lookup(const VelocityGrid& grid, glm::dvec3 p, int weight_steps = 0);
glm::vec3 grid_lookup(const VelocityGrid& grid, glm::vec3 p, int weight_steps = 0);

}  // namespace gsv
