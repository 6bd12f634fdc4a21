#include "support/raycast/proxy_geometry.h"

#include "common/core/error.h"
#include "support/raycast/proxy_ray.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace gsv {

ProxyGeometry::ProxyGeometry(const std::vector<Plane>& clip_planes)
    : given_(clip_planes), polyhedron_(ConvexPolyhedron::unit_cube()) {
    for (std::size_t i = 0; i < clip_planes.size(); ++i)
        planes_.push_back(normalized(clip_planes[i], "clip plane " + std::to_string(i)));
    for (std::size_t i = 0; i < planes_.size(); ++i) polyhedron_.clip(planes_[i], kFirstClipTag + int(i));
}

MeshData ProxyGeometry::mesh() const { return polyhedron_.triangles(); }

bool ProxyGeometry::contains(glm::dvec3 p) const {
    // Written so that a NaN coordinate answers false.
    for (int axis = 0; axis < 3; ++axis)
        if (!(p[axis] >= 0.0 && p[axis] <= 1.0)) return false;
    // The planes as given, as ray_span() takes them: unit normals would round differently.
    for (const Plane& plane : given_)
        if (!plane.keeps(p)) return false;
    return true;
}

MeshData ProxyGeometry::near_cap(const Plane& near_plane, double offset) const {
    if (!(offset >= 0.0) || !std::isfinite(offset)) {
        char text[96];
        std::snprintf(text, sizeof text, "near cap: offset %g must be a finite distance >= 0", offset);
        throw Error(text);
    }
    Plane moved = normalized(near_plane, "near plane");
    // The normal points at the camera, so a smaller offset moves the plane away from it.
    moved.offset -= offset;
    ConvexPolyhedron seen = polyhedron_;
    seen.clip(moved, kNearCapTag);
    return seen.triangles(kNearCapTag);
}

std::optional<RaySpan> ProxyGeometry::ray_span(glm::dvec3 origin, glm::dvec3 direction) const {
    return ray_proxy_span(origin, direction, given_);
}

Plane near_plane(glm::dvec3 eye, glm::dvec3 forward, double near_distance) {
    const auto finite = [](glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (!finite(eye) || !finite(forward) || forward == glm::dvec3(0.0) || !std::isfinite(near_distance)) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "near plane: eye (%g, %g, %g), forward (%g, %g, %g) and near distance %g must be finite, "
                      "forward non-zero", eye.x, eye.y, eye.z, forward.x, forward.y, forward.z, near_distance);
        throw Error(text);
    }
    const Plane unit = normalized(Plane{-forward, 0.0}, "near plane");
    // Kept: dot(forward, x - eye) >= near, that is dot(-forward, x) <= -dot(forward, eye) - near.
    return Plane{unit.normal, glm::dot(unit.normal, eye) - near_distance};
}

}  // namespace gsv
