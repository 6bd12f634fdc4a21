#pragma once
// Where a ray o + t d crosses an axis-aligned box: a raycaster's entry and exit, on the CPU in double.
//
// The textbook slab method multiplies (box - o) by 1 / d. A direction component of exactly 0 gives
// 1 / 0 = inf, which is fine, until the origin lies on that slab's face: (box - o) = 0 and 0 * inf = NaN,
// and the NaN then wins or loses every min and max at random. Here a zero component is decided on its own
// (the ray is inside that slab for every t, or for none), so axis-aligned rays and rays along a face work.
#include <glm/glm.hpp>

#include <optional>

namespace gsv {

struct RaySpan {
    double entry, exit;  // entry <= exit; equal where the ray only touches an edge or corner
};

// The t at which the whole line o + t d enters and leaves [box_min, box_max] (entry may be negative: a
// caller whose camera is inside the box clamps it to 0), or nothing when the line misses the box. Throws
// gsv::Error for a zero or non-finite direction, a non-finite origin, or box_min > box_max on an axis.
std::optional<RaySpan> ray_box_span(glm::dvec3 origin, glm::dvec3 direction, glm::dvec3 box_min, glm::dvec3 box_max);

}  // namespace gsv
