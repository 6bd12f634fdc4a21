#pragma once
// A scene's velocity field sampled onto an n x n x n grid over D = [-1,1]^3: what lab 05 uploads as a 3D
// texture, and the CPU's emulation of the texture's GL_LINEAR, GL_CLAMP_TO_EDGE lookup, so that an
// integration through the grid can be checked on the CPU like one through the formula.
//
// The emulation is the filter as the GL specification states it (section 8.14.2 of GL 4.6) with exact
// weights. Real hardware rounds the weights to a few fractional bits (8 on NVIDIA, per the CUDA
// programming guide's texture fetching appendix), so a GPU lookup can differ from this one by up to about
// 1/512 of the difference between neighbouring texels; compare GPU results against it with that in mind.
#include "support/particles/particle_motion.h"

#include <glm/glm.hpp>

#include <vector>

namespace gsv {

class VelocityGrid {
public:
    int n = 0;
    // 3 floats (u_x, u_y, u_z) per texel, x fastest, then y, then z: the layout glTexImage3D takes with
    // GL_RGB and GL_FLOAT, texel (i, j, k) at 3 * ((k n + j) n + i). Size 3 n^3.
    std::vector<float> texels;

    // Texel (i, j, k)'s centre is p = -1 + (2i + 1) / n along x (and likewise along y and z), where the
    // field is evaluated in double and rounded to float. Throws gsv::Error for n outside kMinSide ..
    // kMaxSide (512^3 texels are 1.5 GiB) and for Gravity, which has no field.
    static constexpr int kMinSide = 2, kMaxSide = 512;
    static VelocityGrid sample(ParticleScene scene, int n);

    // Texel (i, j, k) as stored. Throws gsv::Error outside the grid.
    glm::vec3 texel(int i, int j, int k) const;

    // What GL_LINEAR with GL_CLAMP_TO_EDGE returns at texture coordinate s = (p + 1) / 2: per axis
    // x = s n - 1/2, i0 = floor(x), f = x - i0, texels i0 and i0 + 1 each clamped to 0 .. n-1, then the
    // trilinear mix. So a texel centre gives that texel, and the outer half texel (and anything beyond
    // D) gives the edge value. The double version computes in double from the float texels; the float one
    // computes each step in float, as the float CPU run does. A NaN coordinate gives NaN.
    glm::dvec3 lookup(glm::dvec3 p) const;
    glm::vec3 lookup(glm::vec3 p) const;
};

}  // namespace gsv
