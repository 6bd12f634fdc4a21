// Procedural terrains with exact gradients: Franke's function, the sin-cos egg-crate and flat ground.
#include "support/terrain/terrain_procedural.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"

#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Franke's four Gaussian terms, each as weight * exp(exponent) with the exponent's partial derivatives in
// a = 9u and b = 9v, so value and gradient come from one evaluation of each exp and one statement of the
// formula.
struct FrankeTerm {
    double value;
    glm::dvec2 d_exponent;
};

void franke_terms(double u, double v, FrankeTerm terms[4]) {
    const double a = 9 * u, b = 9 * v;
    terms[0] = {0.75 * std::exp(-((a - 2) * (a - 2) + (b - 2) * (b - 2)) / 4), {-(a - 2) / 2, -(b - 2) / 2}};
    terms[1] = {0.75 * std::exp(-(a + 1) * (a + 1) / 49 - (b + 1) / 10), {-2 * (a + 1) / 49, -0.1}};
    terms[2] = {0.5 * std::exp(-((a - 7) * (a - 7) + (b - 3) * (b - 3)) / 4), {-(a - 7) / 2, -(b - 3) / 2}};
    terms[3] = {-0.2 * std::exp(-(a - 4) * (a - 4) - (b - 7) * (b - 7)), {-2 * (a - 4), -2 * (b - 7)}};
}

void check_terrain(const ProceduralTerrain& terrain, glm::dvec2 ground_m) {
    if (!std::isfinite(terrain.extent_m) || terrain.extent_m <= 0)
        throw Error("procedural terrain: extent " + std::to_string(terrain.extent_m) + " m must be positive and finite");
    if (!std::isfinite(terrain.amplitude_m))
        throw Error("procedural terrain: amplitude " + std::to_string(terrain.amplitude_m) + " m must be finite");
    if (!std::isfinite(ground_m.x) || !std::isfinite(ground_m.y))
        throw Error("procedural terrain: ground point (" + std::to_string(ground_m.x) + ", " +
                    std::to_string(ground_m.y) + ") m must be finite");
}

double unit_height(TerrainKind kind, double u, double v) {
    switch (kind) {
        case TerrainKind::Flat: return 0.0;
        case TerrainKind::Franke: return franke(u, v);
        case TerrainKind::SinCos: return sin_cos(u, v);
    }
    throw Error("procedural terrain: unknown kind " + std::to_string(static_cast<int>(kind)));
}

glm::dvec2 unit_gradient(TerrainKind kind, double u, double v) {
    switch (kind) {
        case TerrainKind::Flat: return {0.0, 0.0};
        case TerrainKind::Franke: return franke_gradient(u, v);
        case TerrainKind::SinCos: return sin_cos_gradient(u, v);
    }
    throw Error("procedural terrain: unknown kind " + std::to_string(static_cast<int>(kind)));
}

}  // namespace

double franke(double u, double v) {
    FrankeTerm terms[4];
    franke_terms(u, v, terms);
    return terms[0].value + terms[1].value + terms[2].value + terms[3].value;
}

glm::dvec2 franke_gradient(double u, double v) {
    FrankeTerm terms[4];
    franke_terms(u, v, terms);
    glm::dvec2 gradient(0.0);
    // d/du exp(E(9u, 9v)) = exp(E) * dE/da * 9; the exponents' derivatives above are per a = 9u, b = 9v.
    for (const FrankeTerm& term : terms) gradient += term.value * term.d_exponent * 9.0;
    return gradient;
}

double sin_cos(double u, double v) {
    const double w = 2 * kPi * kSinCosPeriods;
    return std::sin(w * u) * std::cos(w * v);
}

glm::dvec2 sin_cos_gradient(double u, double v) {
    const double w = 2 * kPi * kSinCosPeriods;
    return {w * std::cos(w * u) * std::cos(w * v), -w * std::sin(w * u) * std::sin(w * v)};
}

TerrainKind terrain_kind_from_name(const std::string& name) { return parse_enum(kTerrainKindNames, "terrain", name); }
const char* terrain_kind_name(TerrainKind kind) { return name_of(kTerrainKindNames, kind); }

double terrain_height(const ProceduralTerrain& terrain, glm::dvec2 ground_m) {
    check_terrain(terrain, ground_m);
    return terrain.amplitude_m * unit_height(terrain.kind, ground_m.x / terrain.extent_m, ground_m.y / terrain.extent_m);
}

glm::dvec2 terrain_slope(const ProceduralTerrain& terrain, glm::dvec2 ground_m) {
    check_terrain(terrain, ground_m);
    // The chain rule of u = x / extent: metres of height per metre of ground.
    return terrain.amplitude_m / terrain.extent_m *
           unit_gradient(terrain.kind, ground_m.x / terrain.extent_m, ground_m.y / terrain.extent_m);
}

HeightField make_procedural(const ProceduralTerrain& terrain, int width, int height) {
    if (width < 1 || height < 1 || width > kMaxHeightSide || height > kMaxHeightSide)
        throw Error("make_procedural: size " + std::to_string(width) + "x" + std::to_string(height) + " is not in 1.." +
                    std::to_string(kMaxHeightSide) + " each way");
    check_terrain(terrain, {0.0, 0.0});
    HeightField field;
    field.width = width;
    field.height = height;
    field.dx_m = terrain.extent_m / width;
    field.dy_m = terrain.extent_m / height;
    field.heights.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            field.heights[static_cast<std::size_t>(y) * width + x] =
                static_cast<float>(terrain_height(terrain, sample_position(field, x, y)));
    return field;
}

}  // namespace gsv
