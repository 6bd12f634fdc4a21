#pragma once
// The Marschner-Lobb test signal (S. R. Marschner and R. J. Lobb, "An evaluation of reconstruction filters
// for volume rendering", Proceedings of IEEE Visualization 1994, 100-107): the standard volume for
// judging how a raycaster reconstructs, because much of its energy lies close to the Nyquist rate of the
// usual 41^3 grid (the rings reach 9.4 cycles per unit, the grid resolves 10.25), so every filter's and
// every gradient's error shows. On [-1,1]^3, in double:
//
//   rho(x, y, z) = (1 - sin(pi z / 2) + alpha (1 + rho_r(sqrt(x^2 + y^2)))) / (2 (1 + alpha)),
//   rho_r(r)     = cos(2 pi f_M cos(pi r / 2)),
//
// values in [0, 1]; f_M = 6 and alpha = 0.25 by default. Its isosurfaces are surfaces of revolution about
// the z axis, rippled by the rings.
//
// Sampling convention (the one the kit uses everywhere, support/particles/particle_grid.h and support/terrain/height_field.h
// too): an n^3 volume over [-1,1]^3 holds rho at its TEXEL CENTRES, voxel (i, j, k) at
// p = -1 + (2 (i, j, k) + 1) / n, so texture coordinate s and point p are related by p = 2 s - 1 exactly as
// Volume::sample reads it, and the volume's spacing is 2 / n. (Many implementations put the samples on
// the grid points -1 + 2 i / (n - 1) instead, boundaries included: a texture of those samples would show
// the function shrunk by (n - 1) / n about the centre.)
#include "support/volume/volume.h"

#include <glm/glm.hpp>

#include <optional>

namespace gsv {

struct MarschnerLobb {
    double f_m = 6;       // frequency of the radial rings
    double alpha = 0.25;  // weight of the rings against the z term
};

// rho at p, and its exact gradient (d rho / dx, d rho / dy, d rho / dz), both in double. The gradient is
// finite and continuous on the z axis (r = 0), where the chain rule through sqrt(x^2 + y^2) would divide by
// r: its x and y parts are written with sin(pi r / 2) / r, which tends to pi / 2. Throw gsv::Error for a
// non-finite p or parameter, or alpha = -1.
double marschner_lobb(glm::dvec3 p, const MarschnerLobb& params = {});
glm::dvec3 marschner_lobb_gradient(glm::dvec3 p, const MarschnerLobb& params = {});

// The texture coordinate of point p of [-1,1]^3, and back: s = (p + 1) / 2, p = 2 s - 1.
inline glm::dvec3 marschner_lobb_texcoord(glm::dvec3 p) { return (p + 1.0) * 0.5; }
inline glm::dvec3 marschner_lobb_point(glm::dvec3 texcoord) { return texcoord * 2.0 - 1.0; }

// rho sampled at the texel centres of an n^3 volume over [-1,1]^3 (the convention above), rounded to
// float, with spacing 2 / n, min and max its range and name "marschner_lobb". Throws gsv::Error for n
// outside 2..kMaxVolumeSide or n^3 above kMaxVolumeVoxels.
inline constexpr int kMarschnerLobbSide = 41;
Volume make_marschner_lobb_volume(int n = kMarschnerLobbSide, const MarschnerLobb& params = {});

// The first t in [t0, t1] where the ray origin + t direction meets the isosurface rho = iso inside the
// volume's box [-1,1]^3, or nothing when it does not (it misses the box, or rho - iso keeps its sign): the
// reference for a raycaster's isosurface compositing. [t0, t1] is first clipped to the box (ray_box_span,
// so direction components of exactly 0 work), then marched in steps of at most `step` (in units of p,
// whatever the length of `direction`) for the first sign change of rho - iso, which bisection then closes
// to adjacent doubles (the lower one is returned, or a t where rho == iso exactly). Two crossings closer
// together than `step` (a ray grazing the surface) can be missed, as a raycaster misses them; the default
// resolves the rings (a ring period is at least 2 / (pi f_M) = 0.106 at f_M = 6) some fifty times over.
// Throws gsv::Error for non-finite arguments, a zero direction, t1 < t0, or a step that is not positive or
// so small the march would take over 10^9 steps.
inline constexpr double kMarschnerLobbRayStep = 1.0 / 512;
std::optional<double> marschner_lobb_ray_hit(glm::dvec3 origin, glm::dvec3 direction, double t0, double t1, double iso,
                                             const MarschnerLobb& params = {}, double step = kMarschnerLobbRayStep);

}  // namespace gsv
