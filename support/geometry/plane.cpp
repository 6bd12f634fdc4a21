#include "support/geometry/plane.h"

#include "common/core/error.h"
#include "common/core/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gsv {
namespace {

std::string text(const Plane& plane) {
    return "normal (" + format_number(plane.normal.x) + ", " + format_number(plane.normal.y) + ", " + format_number(plane.normal.z) +
           ") and offset " + format_number(plane.offset);
}

}  // namespace

Plane plane_through(glm::dvec3 point, glm::dvec3 outward) { return Plane{outward, glm::dot(outward, point)}; }

Plane normalized(const Plane& plane, const std::string& what) {
    const glm::dvec3 n = plane.normal;
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z) || !std::isfinite(plane.offset))
        throw Error(what + " has " + text(plane) + ": every number must be finite");
    const double largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
    if (largest == 0.0) throw Error(what + " has a zero normal, so it bounds no half-space (" + text(plane) + ")");
    // Scaled first so that the length is between 1 and sqrt(3) whatever the normal's magnitude.
    const glm::dvec3 scaled = n / largest;
    const double length = glm::length(scaled);
    const Plane result{scaled / length, plane.offset / largest / length};
    if (!std::isfinite(result.offset))
        throw Error(what + " has " + text(plane) + ": its offset overflows once the normal is made unit length");
    return result;
}

}  // namespace gsv
