#pragma once
// A scene's velocity field sampled onto an n x n x n grid over D = [-1,1]^3: what lab 05 uploads as a 3D
// texture. (The CPU's emulation of the shader's lookup in it, L05-T5, is the instructor's:
// reference/particles/grid_lookup.h.)
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
};

}  // namespace gsv
