#pragma once
// Procedural terrains whose exact slopes are known, so lab 04's sweep can measure the error of the normals its
// shader computes by finite differences (against reference/terrain/terrain_normal.h's exact_normal, the
// instructor's) rather than only look at them.
// Everything in double precision; only make_procedural's stored heights are rounded to float.
//
// Each kind is a function f(u, v) on the unit square with its analytic gradient; a ProceduralTerrain
// stretches it over a ground square of extent_m metres and scales it by amplitude_m:
//   h(x, z) = amplitude_m * f(x / extent_m, z / extent_m),   (dh/dx, dh/dz) = amplitude_m / extent_m * grad f,
// with x along the field's columns and z along its rows (x east, z north).
#include "common/core/enum_names.h"
#include "support/terrain/height_field.h"

#include <glm/glm.hpp>

#include <string>

namespace gsv {

// Franke's test function (R. Franke, "A critical comparison of some methods for interpolation of scattered
// data", Naval Postgraduate School report NPS-53-79-003, Monterey, 1979): two broad hills, a ridge and a
// dip, values about 0 .. 1.22 on [0,1]^2, the standard test surface for interpolation.
double franke(double u, double v);
glm::dvec2 franke_gradient(double u, double v);

// sin(2 pi k u) cos(2 pi k v) with k = kSinCosPeriods periods across the square: a regular egg-crate of
// hills and hollows, values in [-1, 1], whose curvature is the same everywhere.
inline constexpr double kSinCosPeriods = 2;
double sin_cos(double u, double v);
glm::dvec2 sin_cos_gradient(double u, double v);

// Flat is height 0 everywhere: its normal is exactly up, the case where any error is a bug.
enum class TerrainKind { Flat, Franke, SinCos };
inline constexpr EnumName<TerrainKind> kTerrainKindNames[] = {
    {TerrainKind::Franke, "franke"}, {TerrainKind::SinCos, "sin_cos"}, {TerrainKind::Flat, "flat"}};

// A name of kTerrainKindNames; any other throws gsv::Error listing them.
TerrainKind terrain_kind_from_name(const std::string& name);
const char* terrain_kind_name(TerrainKind kind);

struct ProceduralTerrain {
    TerrainKind kind = TerrainKind::Franke;
    double extent_m = 1000;    // side of the ground square [0, extent_m]^2 the unit square is stretched over
    double amplitude_m = 100;  // heights are amplitude_m * f
};

// Height in metres and slope (dh/dx, dh/dz, metres per metre) at ground point (x, z) in metres. Defined
// everywhere, not only on the square. Throw gsv::Error for an extent that is not positive and finite, an
// amplitude or a point that is not finite.
double terrain_height(const ProceduralTerrain& terrain, glm::dvec2 ground_m);
glm::dvec2 terrain_slope(const ProceduralTerrain& terrain, glm::dvec2 ground_m);

// The terrain sampled at the centres of a width x height grid over its square: dx_m = extent_m / width,
// dy_m = extent_m / height (a non-square grid has non-square cells), heights rounded to float. Throws
// gsv::Error for a size outside 1..kMaxHeightSide or a terrain terrain_height refuses.
HeightField make_procedural(const ProceduralTerrain& terrain, int width, int height);

}  // namespace gsv
