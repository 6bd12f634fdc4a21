// Plane-by-plane clipping of a convex polyhedron on a shared vertex list, and its triangulation for GL.
#include "support/geometry/convex_polyhedron.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <utility>

namespace gsv {
namespace {

using Index = std::uint32_t;
using Edge = std::pair<Index, Index>;

Edge undirected(Index a, Index b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// Union-find over vertex indices; the representative of a set is its smallest index, so a weld keeps an
// old vertex (which other cuts already rely on) over a new one.
struct Welds {
    std::vector<Index> parent;
    explicit Welds(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), Index{0}); }
    Index find(Index v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    }
    void join(Index a, Index b) {
        a = find(a), b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

// Drops repeats of a vertex next to itself, the closing pair (last, first) included.
void remove_repeats(std::vector<Index>& loop) {
    loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
    while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
}

// Removes every vertex that fewer than three faces share, until none is left. A vertex of a convex
// polyhedron has at least three faces; one with two lies on the edge where they meet, within the epsilon,
// and between the same two neighbours in both (a -> v -> b in one, b -> v -> a in the other, since each
// of its two edges is shared). Taking it out of both keeps every edge paired. It appears where two planes
// nearly parallel leave a body thinner than the epsilon over their angle: there a vertex on both planes
// within the epsilon can be far enough from its neighbours not to be welded, and the faces either side
// would overlap in a fold of zero volume whose triangles duplicate each other.
void remove_vertices_of_two_faces(std::vector<ConvexPolyhedron::Face>& faces) {
    while (true) {
        std::map<Index, int> face_count;
        for (const ConvexPolyhedron::Face& face : faces) {
            std::vector<Index> distinct = face.loop;
            std::sort(distinct.begin(), distinct.end());
            distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
            for (Index v : distinct) ++face_count[v];
        }
        const auto lonely = [&](Index v) { return face_count[v] < 3; };
        bool changed = false;
        for (ConvexPolyhedron::Face& face : faces) {
            const std::size_t before = face.loop.size();
            face.loop.erase(std::remove_if(face.loop.begin(), face.loop.end(), lonely), face.loop.end());
            remove_repeats(face.loop);
            changed |= face.loop.size() != before;
        }
        faces.erase(std::remove_if(faces.begin(), faces.end(),
                                   [](const ConvexPolyhedron::Face& face) { return face.loop.size() < 3; }),
                    faces.end());
        if (!changed) return;
    }
}

// Whether every vertex lies within kPlaneEpsilon below the plane of some face, taken through the face's
// outermost corner (faces are planar only up to the epsilon).
bool thinner_than_epsilon(const std::vector<glm::dvec3>& vertices, const std::vector<ConvexPolyhedron::Face>& faces) {
    for (const ConvexPolyhedron::Face& face : faces) {
        double top = -std::numeric_limits<double>::infinity();
        for (Index v : face.loop) top = std::max(top, glm::dot(face.normal, vertices[v]));
        bool thin = true;
        for (const ConvexPolyhedron::Face& other : faces)
            for (Index v : other.loop) thin = thin && glm::dot(face.normal, vertices[v]) > top - kPlaneEpsilon;
        if (thin) return true;
    }
    return false;
}

// A closed walk cut into simple loops wherever it comes back to a vertex it has passed: a degenerate
// face that touches itself at a vertex becomes two faces, each a simple polygon a fan can triangulate.
// Pieces of fewer than three vertices (a walk there and back along one edge) enclose nothing.
void append_simple_loops(const std::vector<Index>& walk, std::vector<std::vector<Index>>& loops) {
    std::vector<Index> path;
    std::map<Index, std::size_t> position;
    for (Index v : walk) {
        const auto seen = position.find(v);
        if (seen == position.end()) {
            position.emplace(v, path.size());
            path.push_back(v);
            continue;
        }
        const std::size_t k = seen->second;
        if (path.size() - k >= 3) loops.emplace_back(path.begin() + std::ptrdiff_t(k), path.end());
        for (std::size_t i = k + 1; i < path.size(); ++i) position.erase(path[i]);
        path.resize(k + 1);
    }
    if (path.size() >= 3) loops.push_back(std::move(path));
}

// The loops that the unpaired directed edges form, each walked against its edges' direction: the holes a
// cut leaves, wound the way the face that closes them must be. Every vertex of the holes has as many
// unpaired edges in as out (each face is a closed loop and pairs take one of each), so each walk returns
// to its start.
std::vector<std::vector<Index>> hole_loops(const std::vector<ConvexPolyhedron::Face>& faces) {
    std::map<Edge, int> net;  // (a < b): uses of a -> b minus uses of b -> a
    for (const ConvexPolyhedron::Face& face : faces)
        for (std::size_t i = 0; i < face.loop.size(); ++i) {
            const Index a = face.loop[i], b = face.loop[(i + 1) % face.loop.size()];
            net[undirected(a, b)] += a < b ? 1 : -1;
        }
    std::map<Index, std::vector<Index>> next;  // reversed unpaired edges, from -> to
    for (const auto& [edge, count] : net)
        for (int k = 0; k < std::abs(count); ++k) {
            if (count > 0) next[edge.second].push_back(edge.first);
            else next[edge.first].push_back(edge.second);
        }
    std::vector<std::vector<Index>> loops;
    for (auto& [start, targets] : next)
        while (!targets.empty()) {
            std::vector<Index> walk{start};
            Index at = start;
            while (true) {
                std::vector<Index>& out = next[at];
                if (out.empty()) break;  // unreachable for balanced edges; stops rather than loops forever
                at = out.back();
                out.pop_back();
                if (at == start) break;
                walk.push_back(at);
            }
            append_simple_loops(walk, loops);
        }
    return loops;
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::unit_cube() {
    ConvexPolyhedron cube;
    // Vertex i is at (i & 1, i >> 1 & 1, i >> 2 & 1).
    for (Index i = 0; i < 8; ++i) cube.vertices_.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    cube.faces_ = {
        {{0, 4, 6, 2}, {-1, 0, 0}, 0}, {{1, 3, 7, 5}, {1, 0, 0}, 1},
        {{0, 1, 5, 4}, {0, -1, 0}, 2}, {{2, 6, 7, 3}, {0, 1, 0}, 3},
        {{0, 2, 3, 1}, {0, 0, -1}, 4}, {{4, 5, 7, 6}, {0, 0, 1}, 5},
    };
    return cube;
}

void ConvexPolyhedron::clip(const Plane& plane, int tag) {
    if (!(std::abs(glm::length(plane.normal) - 1.0) < 1e-12) || !std::isfinite(plane.offset))
        throw Error("ConvexPolyhedron::clip: the plane for tag " + std::to_string(tag) +
                    " needs a unit normal and a finite offset (use gsv::normalized)");
    if (faces_.empty()) return;

    // -1 inside, 0 on the plane, +1 outside. Every vertex is used: clip() compacts the list at its end.
    std::vector<double> distance(vertices_.size());
    std::vector<int> side(vertices_.size());
    bool any_inside = false, any_outside = false;
    for (std::size_t v = 0; v < vertices_.size(); ++v) {
        distance[v] = plane.signed_distance(vertices_[v]);
        side[v] = distance[v] < -kPlaneEpsilon ? -1 : distance[v] > kPlaneEpsilon ? 1 : 0;
        any_inside |= side[v] < 0;
        any_outside |= side[v] > 0;
    }
    if (!any_outside) return;
    if (!any_inside) {
        vertices_.clear();
        faces_.clear();
        return;
    }

    // One crossing point per cut edge, computed from its inside end so that both faces get the same bits.
    // It lies at least |distance[inside]| > kPlaneEpsilon from either end of its edge.
    std::map<Edge, Index> crossing;
    const auto crossing_point = [&](Index a, Index b) {
        const auto [found, inserted] = crossing.try_emplace(undirected(a, b), Index(vertices_.size()));
        if (inserted) {
            const Index in = side[a] < 0 ? a : b, out = side[a] < 0 ? b : a;
            const double t = distance[in] / (distance[in] - distance[out]);  // in (0, 1): opposite signs
            vertices_.push_back(vertices_[in] + t * (vertices_[out] - vertices_[in]));
        }
        return found->second;
    };

    std::vector<Face> kept;
    for (const Face& face : faces_) {
        const std::size_t n = face.loop.size();
        // A face with no corner strictly inside lies on or beyond the plane: at most a sliver of it is
        // kept, which the cap covers.
        if (std::none_of(face.loop.begin(), face.loop.end(), [&](Index v) { return side[v] < 0; })) continue;
        Face cut{{}, face.normal, face.tag};
        for (std::size_t i = 0; i < n; ++i) {
            const Index a = face.loop[i], b = face.loop[(i + 1) % n];
            if (side[a] <= 0) cut.loop.push_back(a);
            if (side[a] * side[b] < 0) cut.loop.push_back(crossing_point(a, b));
        }
        kept.push_back(std::move(cut));
    }

    // Weld the edges along the plane shorter than the epsilon: where a cut passes just beyond a vertex,
    // the crossings on its edges crowd together. Only edges between points on the plane can be that
    // short, since any other vertex is more than kPlaneEpsilon from the plane. Edges only, not every close
    // pair: two points that no edge joins have the face between them, and welding them would pinch it.
    const auto on_plane = [&](Index v) { return v >= side.size() || side[v] == 0; };
    Welds welds(vertices_.size());
    for (const Face& face : kept)
        for (std::size_t i = 0; i < face.loop.size(); ++i) {
            const Index a = face.loop[i], b = face.loop[(i + 1) % face.loop.size()];
            if (on_plane(a) && on_plane(b) && glm::length(vertices_[a] - vertices_[b]) < kPlaneEpsilon)
                welds.join(a, b);
        }
    faces_.clear();
    for (Face& face : kept) {
        for (Index& v : face.loop) v = welds.find(v);
        remove_repeats(face.loop);
        std::vector<std::vector<Index>> loops;
        append_simple_loops(face.loop, loops);
        for (std::vector<Index>& loop : loops) faces_.push_back(Face{std::move(loop), face.normal, face.tag});
    }

    for (std::vector<Index>& loop : hole_loops(faces_)) faces_.push_back(Face{std::move(loop), plane.normal, tag});
    remove_vertices_of_two_faces(faces_);
    // Fewer than four faces enclose nothing, and a body within the epsilon of one of its face planes is a
    // sheet (a cut at a shallow angle to an earlier one can leave one, while itself keeping a vertex more
    // than the epsilon inside): both are empty, as a body thinner than the epsilon along a cut's normal is.
    if (faces_.size() < 4 || thinner_than_epsilon(vertices_, faces_)) faces_.clear();

    // Compact: drop the vertices no face uses any more, keeping the order of the rest.
    std::vector<Index> renumber(vertices_.size(), Index(-1));
    for (const Face& face : faces_)
        for (Index v : face.loop) renumber[v] = 0;
    std::vector<glm::dvec3> used;
    for (std::size_t v = 0; v < vertices_.size(); ++v)
        if (renumber[v] == 0) {
            renumber[v] = Index(used.size());
            used.push_back(vertices_[v]);
        }
    vertices_ = std::move(used);
    for (Face& face : faces_)
        for (Index& v : face.loop) v = renumber[v];
}

double ConvexPolyhedron::face_area(const Face& face) const {
    const glm::dvec3 p0 = vertices_[face.loop[0]];
    glm::dvec3 twice_area(0.0);
    for (std::size_t i = 1; i + 1 < face.loop.size(); ++i)
        twice_area += glm::cross(vertices_[face.loop[i]] - p0, vertices_[face.loop[i + 1]] - p0);
    return 0.5 * glm::dot(twice_area, face.normal);
}

double ConvexPolyhedron::volume() const {
    if (faces_.empty()) return 0.0;
    // Tetrahedra from a vertex of the polyhedron rather than from the origin: smaller terms, less cancellation.
    const glm::dvec3 apex = vertices_[0];
    double six_volume = 0.0;
    for (const Face& face : faces_) {
        const glm::dvec3 p0 = vertices_[face.loop[0]] - apex;
        for (std::size_t i = 1; i + 1 < face.loop.size(); ++i)
            six_volume += glm::dot(p0, glm::cross(vertices_[face.loop[i]] - apex, vertices_[face.loop[i + 1]] - apex));
    }
    return six_volume / 6.0;
}

MeshData ConvexPolyhedron::triangles(int tag) const {
    // A triangle is a sliver when its smallest height (twice its area over its longest side) is within the
    // epsilon: as thin as the clipper's resolution, and in float32 perhaps of zero area.
    const auto sliver = [](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
        const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
        return !(glm::length(glm::cross(b - a, c - a)) > kPlaneEpsilon * longest);
    };
    MeshData mesh;
    for (const Face& face : faces_) {
        if (tag != kAllFaces && face.tag != tag) continue;
        std::vector<glm::dvec3> corners;
        for (Index v : face.loop) corners.push_back(vertices_[v]);
        const std::size_t n = corners.size();
        std::size_t apex = 0;
        for (; apex < n; ++apex) {
            bool good = true;
            for (std::size_t i = 1; i + 1 < n && good; ++i)
                good = !sliver(corners[apex], corners[(apex + i) % n], corners[(apex + i + 1) % n]);
            if (good) break;
        }
        const auto first = static_cast<Index>(mesh.positions.size());
        const glm::vec3 normal(face.normal);
        for (const glm::dvec3& p : corners) {
            mesh.positions.emplace_back(p);
            mesh.normals.push_back(normal);
        }
        if (apex < n) {
            for (std::size_t i = 1; i + 1 < n; ++i)
                mesh.indices.insert(mesh.indices.end(), {first + Index(apex), first + Index((apex + i) % n),
                                                         first + Index((apex + i + 1) % n)});
        } else {
            // Every corner's fan has a sliver, so the face has several nearly straight corners. The centroid
            // of a convex polygon lies inside it, away from every side.
            glm::dvec3 centroid(0.0);
            for (const glm::dvec3& p : corners) centroid += p;
            mesh.positions.emplace_back(centroid / double(n));
            mesh.normals.push_back(normal);
            const auto centre = static_cast<Index>(mesh.positions.size() - 1);
            for (std::size_t i = 0; i < n; ++i)
                mesh.indices.insert(mesh.indices.end(), {centre, first + Index(i), first + Index((i + 1) % n)});
        }
    }
    return mesh;
}

}  // namespace gsv
