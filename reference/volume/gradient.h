#pragma once
// The CPU reference of lab 06's gradient modules: finite differences of a Volume, in double, in physical
// units (value per unit of spacing, e.g. per mm), and the normalisation a shading module applies to them.
//
// Physical units matter because voxels are rarely cubes: a difference per voxel along a 2 mm axis and one
// along a 0.5 mm axis are not comparable until each is divided by its own spacing, and a normal built from
// differences per voxel tilts toward the coarse axis.
//
// At a voxel, neighbours beyond the grid are the edge voxel, as the GPU's CLAMP_TO_EDGE lookups one texel
// away give them: the central difference at a border is half the one-sided one, and the forward
// difference at the last voxel of an axis is 0 along it. At a texture coordinate, the differences go
// through Volume::sample, exactly as a shader's texture() calls do; at a texel centre, with a step of one
// voxel, they equal the voxel versions.
// In reference/, the instructor's: linked by the solutions and the tests, never by a student's build.
#include "support/volume/volume.h"

#include <glm/glm.hpp>

namespace gsv {

// (v(i+1) - v(i-1)) / (2 sx), and so on along y and z; neighbours clamped to the grid. Throws gsv::Error
// for a voxel outside the grid, a malformed volume, or a spacing that is not positive and finite.
glm::dvec3 central_difference(const Volume& volume, int i, int j, int k);
// (v(i+1) - v(i)) / sx, and so on; neighbours clamped to the grid. Throws as central_difference does.
glm::dvec3 forward_difference(const Volume& volume, int i, int j, int k);

// The same through Volume::sample at texture coordinate s, with neighbours step_voxels voxels away along
// each axis (texture offsets step_voxels / n per axis, physical distance step_voxels times the spacing).
// Throws gsv::Error for a malformed volume, a bad spacing, or a step_voxels that is not positive and finite.
glm::dvec3 central_difference(const Volume& volume, glm::dvec3 texcoord, double step_voxels = 1.0);
glm::dvec3 forward_difference(const Volume& volume, glm::dvec3 texcoord, double step_voxels = 1.0);

// g / |g|, and the zero vector for g = 0 (a constant region's gradient), where normalize() gives 0/0 = NaN
// and a NaN normal turns a shaded pixel black or white. g is scaled by its largest component first, so a
// gradient whose squared length underflows (|g| < 1e-154) or overflows still gets a unit direction. A NaN
// or infinite component gives NaN, so a broken gradient shows rather than hides.
glm::dvec3 safe_normalize(glm::dvec3 gradient);

}  // namespace gsv
