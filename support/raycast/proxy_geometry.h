#pragma once
// The proxy geometry of a GPU raycaster after Voreen: the volume's bounding box, cut by clipping planes,
// drawn with its texture coordinates as colours. Front faces drawn into one image give each pixel's ray
// entry point, back faces into another its exit point, both as texture coordinates. Clipping the box
// moves the entry and exit points with no change to the raycaster, and a near-plane cap keeps entry
// points when the camera is inside the volume. No GL here: the lab uploads these meshes with GpuMesh.
//
// Everything is in texture space, the unit cube [0,1]^3 of the volume's 3D texture, where a plane means
// the same voxels whatever the volume's shape. The meshes' positions ARE the texture coordinates, so the
// vertex shader passes aVertex (gl_Vertex in compat) on as the colour and places it with
// Transforms::model = VolumeBox::model_from_texture_matrix() (support/volume/volume_box.h): MeshData has room for
// a 3D position but only a 2D texture coordinate.
//
// How the GL side draws the entry and exit images:
//   exit image:   clear to 0, depth cleared to 0, glDepthFunc(GL_GREATER), cull GL_FRONT, draw mesh().
//                 (The farthest back face, though for a convex mesh there is only one per pixel.)
//   entry image:  clear to 0, depth cleared to 1, glDepthFunc(GL_LESS), cull GL_BACK, draw mesh(); then,
//                 with the same state, draw near_cap(texture-space near plane). Where the camera's near
//                 plane cuts the proxy, the front faces there lie behind the camera or before the near
//                 plane and were clipped, leaving holes; the cap fills exactly those. It cannot hide a
//                 front face: a convex body is entered once, so where the cap (a point inside the body)
//                 is, that pixel's front face lies before the near plane. The cap lies kNearCapOffset
//                 beyond the near plane so that clipping does not eat it, and it faces the camera.
//   Alpha 0 in the entry image then means "no ray". Skip the draw for an empty mesh (GpuMesh refuses
//   one): clip planes can remove everything, and a cap is empty whenever the near plane misses the proxy.
// Equivalent: add the near plane, its offset lowered by kNearCapOffset, as one more clip plane, and draw
// that one closed mesh for both images (it rebuilds the proxy whenever the camera moves).
#include "common/scene/mesh_data.h"
#include "support/geometry/convex_polyhedron.h"
#include "support/geometry/plane.h"
#include "support/geometry/ray_box.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace gsv {

// Tags of the polyhedron's faces: 0 .. 5 the cube's sides (-x, +x, -y, +y, -z, +z), kFirstClipTag + i
// the cap that clip plane i cuts, kNearCapTag the near-plane cap.
inline constexpr int kFirstClipTag = 6;
inline constexpr int kNearCapTag = -1;

// How far beyond the near plane the cap is drawn, in texture units along the plane's normal: 1e-4 of
// the box. At least 1e-4 times the box's smallest model side, it is far above float32's rounding of a
// vertex at a few model units (about 2e-7), so the cap survives near-plane clipping; a ray starting that
// much late misses a tenth of a voxel at 1000 voxels. A GL side with an extreme aspect ratio or
// depth range can pass its own.
inline constexpr double kNearCapOffset = 1e-4;

class ProxyGeometry {
public:
    // The unit cube cut by each plane in turn (texture space, keeping dot(normal, x) <= offset; normals of
    // any length). Throws gsv::Error naming "clip plane i" for a zero normal or a non-finite number.
    explicit ProxyGeometry(const std::vector<Plane>& clip_planes = {});

    const std::vector<Plane>& clip_planes() const { return planes_; }  // with unit normals
    const ConvexPolyhedron& polyhedron() const { return polyhedron_; }
    bool empty() const { return polyhedron_.empty(); }

    // The clipped box as triangles wound counter-clockwise seen from outside: positions are texture
    // coordinates (the colours), normals the outward face normals in texture space. The unclipped box is
    // 12 triangles. Empty when the planes remove everything.
    MeshData mesh() const;

    // Whether a texture-space point (the camera: VolumeBox::texture_from_model(eye)) lies in the box and
    // on the kept side of every plane, decided exactly with the boundary inside, as ray_span() does. The
    // polyhedron may differ from this by kPlaneEpsilon.
    bool contains(glm::dvec3 texture_point) const;

    // The near-plane cap: the clipped polyhedron's cross-section with `near_plane` (texture space, keeping
    // what the camera sees, so its normal points back at the camera: near_plane() below, then
    // VolumeBox::texture_plane), moved `offset` away from the camera, as triangles wound counter-clockwise
    // seen from the camera. Positions are texture coordinates, as in mesh(). Empty when the plane misses
    // the proxy or the proxy lies wholly behind it. Note that the cap depends on the near plane, not on
    // whether the eye is inside: an eye just outside whose near plane reaches into the box needs it too.
    // Throws gsv::Error for a bad plane or an offset that is negative or not finite.
    MeshData near_cap(const Plane& near_plane, double offset = kNearCapOffset) const;

    // ray_proxy_span (support/raycast/proxy_ray.h) with the clip planes as given: the exact reference.
    std::optional<RaySpan> ray_span(glm::dvec3 origin, glm::dvec3 direction) const;

private:
    std::vector<Plane> given_;   // as passed in: ray_span scales them only by powers of two, exactly
    std::vector<Plane> planes_;
    ConvexPolyhedron polyhedron_;
};

// A camera's near plane as a half-space keeping what the camera sees: the points at least near_distance
// along `forward` (any length) from `eye`, in the space they are given in. Give them in model space and
// convert with VolumeBox::texture_plane: under the box's anisotropic scale a distance in texture units
// would depend on the direction. Throws gsv::Error for a zero forward or a non-finite number.
Plane near_plane(glm::dvec3 eye, glm::dvec3 forward, double near_distance);

}  // namespace gsv
