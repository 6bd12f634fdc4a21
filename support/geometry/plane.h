#pragma once
// A half-space bounded by a plane, the one shape that clipping planes, a camera's near plane and the faces
// of a convex polyhedron all share. One convention everywhere: the plane keeps the points x with
// dot(normal, x) <= offset, so the normal points out of what is kept, as a closed mesh's face normals do.
#include <glm/glm.hpp>

#include <string>

namespace gsv {

struct Plane {
    glm::dvec3 normal{0.0, 0.0, 1.0};
    double offset = 0.0;

    // dot(normal, x) - offset: negative inside, positive outside, in units of |normal|.
    double signed_distance(glm::dvec3 x) const { return glm::dot(normal, x) - offset; }
    bool keeps(glm::dvec3 x) const { return signed_distance(x) <= 0.0; }
};

// The plane through `point` whose outside is the side `outward` points to.
Plane plane_through(glm::dvec3 point, glm::dvec3 outward);

// The same half-space with a unit normal, so signed_distance() is a distance and epsilons mean lengths.
// Normals of any length are accepted, 1e-200 and 1e200 included: the normal is divided by its largest
// component before its length is taken, which can then neither underflow nor overflow. Throws gsv::Error
// naming `what` (e.g. "clip plane 2") for a zero normal or a component or offset that is not finite.
Plane normalized(const Plane& plane, const std::string& what);

}  // namespace gsv
