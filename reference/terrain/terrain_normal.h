#pragma once
// Terrain normals: the CPU reference of what lab 04's shader computes from its height texture (L04-T1, L04-T2),
// the exact normals of the procedural terrains, and the angle that measures how far one normal is from another.
// The instructor's yardstick, kept out of support/ so that no student's copy holds the answers.
//
// Frame: x along the field's columns, y UP, z along its rows (the direction of increasing row, north for
// the real models), matching texture coordinates (s, t) -> (x, z). Sample rows placed at increasing world z
// in GL's right-handed world show a north-up map mirrored when seen from above (x east, y up makes +z
// south); a lab that wants the map as printed places row j at -z and negates the normal's z.
#include "support/terrain/height_field.h"
#include "support/terrain/terrain_procedural.h"

#include <glm/glm.hpp>

namespace gsv {

// The unit upward normal of the surface y = exaggeration * h(x, z) where h has slopes
// slope = (dh/dx, dh/dz) (dimensionless, metres per metre): (-e dh/dx, 1, -e dh/dz) normalised. Zero slopes
// give exactly (0, 1, 0). Finite for every finite slope and any finite exaggeration >= 0, however large.
// Throws gsv::Error for an exaggeration that is negative or not finite.
glm::dvec3 normal_from_slopes(glm::dvec2 slope, double exaggeration);

// The normal at sample (x, y) from differences of the heights `step` samples away, over the real ground
// distances dx_m, dy_m: the normalised cross product of the tangents (2 step dx_m, e dh_x, 0) and
// (0, e dh_z, 2 step dy_m), oriented up. Inside, these are central differences (second order in the step).
// Where a neighbour would fall off the grid, the difference spans only the samples that exist, over their
// true distance: at a border sample a ONE-SIDED difference of `step` samples (first order), not a central
// difference of clamped samples, which would halve the slope there. Along an axis one sample long the slope
// is 0. Throws gsv::Error for a sample outside the grid, step < 1, a field whose height count is not
// width*height or whose spacing is not positive and finite, or an exaggeration normal_from_slopes refuses.
glm::dvec3 finite_difference_normal(const HeightField& field, int x, int y, double exaggeration, int step);

// The exact unit upward normal of y = exaggeration * h(x, z) at ground point (x, z) (normal_from_slopes of
// terrain_slope). exact_normal(terrain, sample_position(field, i, j), e) is the normal that
// finite_difference_normal(field, i, j, e, step) approximates when field = make_procedural(terrain, ...).
glm::dvec3 exact_normal(const ProceduralTerrain& terrain, glm::dvec2 ground_m, double exaggeration = 1);


// The angle in radians between two non-zero vectors, accurate for tiny angles too (atan2 of |a x b| and
// a . b, where acos(a . b) would lose half the digits near 0).
double normal_angle(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace gsv
