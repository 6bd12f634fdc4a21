#pragma once
// The exact reference for a raycaster's entry and exit points: where a ray crosses the texture-space box
// [0,1]^3 cut by clipping planes, in double, with no epsilon. A GPU's entry/exit images and ray setup are
// checked against it.
//
// The slab method with each clipping plane as one more (one-sided) slab. Conventions:
// - The boundary counts as inside: a ray along a face, an edge or a clipping plane hits, and a ray that
//   only touches an edge or a corner gets entry == exit.
// - A direction with a component of exactly 0 (more generally, parallel to a plane: dot(normal, d) == 0
//   exactly) is decided without dividing: inside that slab for every t or for none. So an origin exactly on
//   a slab plane never makes 0 * inf = NaN. A direction merely close to parallel gives t = +-inf at worst,
//   never NaN.
#include "support/geometry/plane.h"
#include "support/geometry/ray_box.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace gsv {

// The t at which the whole line o + t d enters and leaves [0,1]^3 with every plane's keeps() (entry may
// be negative: a camera inside clamps it to 0), or nothing when the line misses. Entry and exit are
// finite unless a direction component is so tiny that crossing the box takes more than ~1e308 steps.
// Planes may have normals of any length: they are scaled by a power of two, which is exact, so a plane
// given as (1, 1, 0) and 1 meets the point (0.25, 0.75, z) at distance 0 exactly. Throws gsv::Error for a
// zero or non-finite direction, a non-finite origin, or a plane normalized() refuses ("clip plane i").
std::optional<RaySpan> ray_proxy_span(glm::dvec3 origin, glm::dvec3 direction, const std::vector<Plane>& planes);

}  // namespace gsv
