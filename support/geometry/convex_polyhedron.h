#pragma once
// A convex polyhedron cut down plane by plane, in double: the clipper behind the raycaster's proxy geometry.
//
// Faces are loops of indices into one shared vertex list, so two faces meeting at an edge hold the very
// same two vertices, and the point where a plane crosses that edge is computed once for both. The mesh
// therefore stays closed (every edge used once in each direction) after any sequence of cuts, without
// comparing floating-point positions.
//
// Epsilon. kPlaneEpsilon = 1e-6, a length in the polyhedron's own units (texture space for the proxy, where
// the box is the unit cube). A vertex within it of a cutting plane counts as on the plane: it is kept and
// becomes a corner of the cap, and a new vertex is made only on an edge whose ends are more than it either
// side, so at least that far from both. Edges of the cap shorter than it are welded. So no edge is
// shorter than 1e-6, 8 float32 units in the last place at 1, and the float mesh handed to GL has no
// repeated vertex and no zero-area triangle. The price, documented rather than accidental: a plane within
// 1e-6 of a vertex or face acts as if it passed through it, and a body left within 1e-6 of one of its
// face planes (thinner than a millionth of the box, a thousandth of a voxel at 1024 voxels) is empty.
//
// Faces are convex and planar only up to the epsilon. Where two nearly parallel planes leave a body about
// as thin as the epsilon, a vertex can be within it of both and yet not welded to its neighbours; the
// clipper then takes out every vertex that fewer than three faces share, which would otherwise fold two
// faces over each other, and splits any face loop that touches itself into simple ones. What remains:
// against planes deliberately placed within 1e-10 .. 1e-4 of earlier corners or nearly parallel to
// earlier planes, about one set of up to 12 planes in 40,000 leaves a face about 1e-6 wide (far below a
// pixel) whose triangles wind against its normal. The mesh stays closed even then. Random planes through
// the box did it in none of 400,000 sets.
#include "common/scene/mesh_data.h"
#include "support/geometry/plane.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace gsv {

inline constexpr double kPlaneEpsilon = 1e-6;

class ConvexPolyhedron {
public:
    struct Face {
        std::vector<std::uint32_t> loop;  // counter-clockwise seen from outside, at least 3 vertices
        glm::dvec3 normal;                 // outward, unit length: the plane the face came from
        int tag;                           // who made it: a cube side, or the caller's tag for a cut
    };

    // [0,1]^3 with its six faces tagged 0 .. 5 for -x, +x, -y, +y, -z, +z.
    static ConvexPolyhedron unit_cube();

    // Keeps the part with plane.keeps(x) and closes the cut with a new face tagged `tag` whose normal is the
    // plane's (one face; more only in the degenerate cases above). A plane keeping every vertex (a face or
    // vertex on it included) changes nothing; one keeping no vertex strictly inside (only a face, edge or
    // vertex on it) leaves the polyhedron empty. The plane must have a unit normal (normalized() in
    // support/geometry/plane.h); throws gsv::Error otherwise.
    void clip(const Plane& plane, int tag);

    bool empty() const { return faces_.empty(); }
    const std::vector<glm::dvec3>& vertices() const { return vertices_; }
    const std::vector<Face>& faces() const { return faces_; }

    // Enclosed volume and the area of one face, from the divergence theorem and the polygon's vector area.
    double volume() const;
    double face_area(const Face& face) const;

    // The faces with the given tag (every face when tag is kAllFaces) as triangles for GL: positions are
    // the vertices, normals the face normals, no texture coordinates. Every face gets its own vertices, so
    // normals stay flat. A face is fanned from a corner whose fan has no sliver triangle (one whose height is
    // below kPlaneEpsilon), or else from its centroid, so no triangle has zero area. Empty in, empty out.
    static constexpr int kAllFaces = -0x7fffffff;
    MeshData triangles(int tag = kAllFaces) const;

private:
    std::vector<glm::dvec3> vertices_;
    std::vector<Face> faces_;
};

}  // namespace gsv
