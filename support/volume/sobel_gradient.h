#pragma once
// The gradient volume lab 06's `precomputed` module looks up: a 3x3x3 Sobel operator at every voxel, in physical
// units (value per unit of spacing). Along each axis the difference of the two neighbouring planes, averaged over
// the 3 x 3 voxels across the axis with weights 1-2-1 each way: smoother than the six-lookup differences a shader
// can afford per sample (the lab's gradient modules), which a volume computed once, before the first frame, can
// afford. Neighbours beyond the grid are the edge voxel, as CLAMP_TO_EDGE reads them. Exact for a linear field
// away from the border, whatever the spacing.
#include "support/volume/volume.h"

#include <glm/glm.hpp>

#include <vector>

namespace gsv {

// The gradient at voxel (i, j, k) from its 27 neighbours, in double. Throws gsv::Error for a voxel outside the
// grid, a malformed volume, or a spacing that is not positive and finite.
glm::dvec3 sobel_gradient(const Volume& volume, int i, int j, int k);

// sobel_gradient at every voxel, 3 floats per voxel in the volume's order (x fastest): what glTexImage3D takes
// with GL_RGB and GL_FLOAT. Computed axis by axis (the kernel is separable), about 9 operations a voxel rather
// than 54. Throws as sobel_gradient does.
std::vector<float> sobel_gradient_volume(const Volume& volume);

}  // namespace gsv
