// The slab method for a ray and an axis-aligned box, with direction components of exactly 0 decided apart.
#include "support/geometry/ray_box.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace gsv {
namespace {

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string text(glm::dvec3 v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

}  // namespace

std::optional<RaySpan> ray_box_span(glm::dvec3 origin, glm::dvec3 direction, glm::dvec3 box_min, glm::dvec3 box_max) {
    if (!finite(origin) || !finite(direction) || direction == glm::dvec3(0.0))
        throw Error("ray_box_span: the ray from " + text(origin) + " along " + text(direction) +
                    " needs a finite origin and a finite, non-zero direction");
    if (!(box_min.x <= box_max.x && box_min.y <= box_max.y && box_min.z <= box_max.z))
        throw Error("ray_box_span: box " + text(box_min) + " .. " + text(box_max) + " has a minimum above its maximum");
    double entry = -std::numeric_limits<double>::infinity(), exit = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const double o = origin[axis], d = direction[axis];
        if (d == 0) {
            // Parallel to this slab: inside it for every t or for none, with no division at all.
            if (o < box_min[axis] || o > box_max[axis]) return std::nullopt;
            continue;
        }
        // Division rather than a product with 1 / d: a tiny d overflows to +-inf, never to NaN.
        const double ta = (box_min[axis] - o) / d, tb = (box_max[axis] - o) / d;
        entry = std::max(entry, std::min(ta, tb));
        exit = std::min(exit, std::max(ta, tb));
    }
    if (entry > exit) return std::nullopt;
    return RaySpan{entry, exit};
}

}  // namespace gsv
