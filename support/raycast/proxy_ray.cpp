// Slabs for the box's faces and one-sided slabs for the clipping planes, parallel ones decided apart.
#include "support/raycast/proxy_ray.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace gsv {
namespace {

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The plane scaled by the power of two that brings its largest normal component into [0.5, 1): exact, so a
// plane given as (1, 1, 0) and 1 meets a point with coordinates summing to 1 at exactly 0, which a unit
// normal (components 1/sqrt(2), rounded) would not promise; and bounded, so no product overflows.
Plane exactly_scaled(const Plane& plane, std::size_t index) {
    normalized(plane, "clip plane " + std::to_string(index));  // for its checks and its error message
    int exponent = 0;
    std::frexp(std::max({std::abs(plane.normal.x), std::abs(plane.normal.y), std::abs(plane.normal.z)}), &exponent);
    return Plane{glm::dvec3(std::ldexp(plane.normal.x, -exponent), std::ldexp(plane.normal.y, -exponent),
                            std::ldexp(plane.normal.z, -exponent)),
                 std::ldexp(plane.offset, -exponent)};
}

std::string text(glm::dvec3 v) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "(%g, %g, %g)", v.x, v.y, v.z);
    return buffer;
}

}  // namespace

std::optional<RaySpan> ray_proxy_span(glm::dvec3 origin, glm::dvec3 direction, const std::vector<Plane>& planes) {
    if (!finite(origin) || !finite(direction) || direction == glm::dvec3(0.0))
        throw Error("ray_proxy_span: the ray from " + text(origin) + " along " + text(direction) +
                    " needs a finite origin and a finite, non-zero direction");
    double entry = -std::numeric_limits<double>::infinity(), exit = std::numeric_limits<double>::infinity();
    // Narrows [entry, exit] to the t with plane.keeps(origin + t direction); false when no t is kept.
    const auto cut = [&](const Plane& plane) {
        const double start = plane.signed_distance(origin);
        const double rate = glm::dot(plane.normal, direction);
        if (rate == 0.0) return start <= 0.0;  // parallel: kept for every t or for none, no division
        // A division, not a product with 1 / rate: a tiny rate overflows to +-inf, and start is finite.
        const double t = -start / rate;
        if (rate > 0.0) exit = std::min(exit, t);
        else entry = std::max(entry, t);
        return true;
    };
    // The box's faces as planes: with axis normals the dot products are exact, so these are the slab
    // method's own numbers.
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 normal(0.0);
        normal[axis] = 1.0;
        if (!cut(Plane{normal, 1.0}) || !cut(Plane{-normal, 0.0})) return std::nullopt;
    }
    for (std::size_t i = 0; i < planes.size(); ++i)
        if (!cut(exactly_scaled(planes[i], i))) return std::nullopt;
    if (entry > exit) return std::nullopt;
    return RaySpan{entry, exit};
}

}  // namespace gsv
