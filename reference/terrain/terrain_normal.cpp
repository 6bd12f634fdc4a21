// Terrain normals from slopes, from finite differences of a HeightField, and exact ones of a procedural terrain.
#include "reference/terrain/terrain_normal.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {
namespace {

// The slope along one axis at index i of n, from heights `stride` floats apart, over the samples within
// `step` that exist: central inside, one-sided at the border, shorter towards it. Differences are taken in
// double so the float heights' own rounding is the only error beside the truncation one.
double slope_along(const float* at, std::ptrdiff_t stride, int i, int n, int step, double spacing) {
    const int back = std::min(step, i), ahead = std::min(step, n - 1 - i);
    if (back + ahead == 0) return 0.0;
    return (double(at[ahead * stride]) - double(at[-back * stride])) / ((back + ahead) * spacing);
}

bool positive_finite(double value) { return std::isfinite(value) && value > 0; }

}  // namespace

glm::dvec3 normal_from_slopes(glm::dvec2 slope, double exaggeration) {
    if (!std::isfinite(exaggeration) || exaggeration < 0)
        throw Error("terrain normal: exaggeration " + std::to_string(exaggeration) + " must be finite and >= 0");
    // Past 1 the vector is divided by the exaggeration (same direction) so e * slope never overflows, and it
    // is brought to a largest component of 1 before normalising so its squared length never underflows.
    // "0.0 -" keeps a zero slope's component +0, so flat ground gives exactly (0, 1, 0).
    const glm::dvec3 n = exaggeration <= 1
                             ? glm::dvec3(0.0 - exaggeration * slope.x, 1.0, 0.0 - exaggeration * slope.y)
                             : glm::dvec3(0.0 - slope.x, 1.0 / exaggeration, 0.0 - slope.y);
    const double largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
    return glm::normalize(n / largest);
}

glm::dvec3 finite_difference_normal(const HeightField& field, int x, int y, double exaggeration, int step) {
    const auto refuse = [](const std::string& what) { throw Error("finite_difference_normal: " + what); };
    const std::size_t count = static_cast<std::size_t>(std::max(field.width, 0)) *
                              static_cast<std::size_t>(std::max(field.height, 0));
    if (field.heights.size() != count || count == 0)
        refuse(std::to_string(field.heights.size()) + " heights for a " + std::to_string(field.width) + "x" +
               std::to_string(field.height) + " field");
    if (!positive_finite(field.dx_m) || !positive_finite(field.dy_m))
        refuse("sample spacing " + std::to_string(field.dx_m) + " x " + std::to_string(field.dy_m) +
               " m must be positive and finite");
    if (x < 0 || y < 0 || x >= field.width || y >= field.height)
        refuse("sample (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
               std::to_string(field.width) + "x" + std::to_string(field.height) + " grid");
    if (step < 1) refuse("step " + std::to_string(step) + " must be at least 1");

    const float* here = field.heights.data() + static_cast<std::size_t>(y) * field.width + x;
    // The tangents' cross product, (-2 step dy_m e dh_x, 4 step^2 dx_m dy_m, -2 step dx_m e dh_z), is this
    // slope form times a positive factor; the slope form keeps huge exaggerations finite.
    const glm::dvec2 slope(slope_along(here, 1, x, field.width, step, field.dx_m),
                           slope_along(here, field.width, y, field.height, step, field.dy_m));
    return normal_from_slopes(slope, exaggeration);
}

glm::dvec3 exact_normal(const ProceduralTerrain& terrain, glm::dvec2 ground_m, double exaggeration) {
    return normal_from_slopes(terrain_slope(terrain, ground_m), exaggeration);
}

double normal_angle(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace gsv
