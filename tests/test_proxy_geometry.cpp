// The raycaster's proxy geometry (support/raycast/proxy_geometry.h), its clipper (support/geometry/convex_polyhedron.h), the
// texture-to-model map (support/volume/volume_box.h) and the exact ray reference (support/raycast/proxy_ray.h).
#include "catch.hpp"
#include "test_support.h"

#include "common/core/error.h"
#include "common/core/splitmix64.h"
#include "support/geometry/convex_polyhedron.h"
#include "support/raycast/proxy_geometry.h"
#include "support/raycast/proxy_ray.h"
#include "support/volume/volume_box.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

using gsv::MeshData;
using gsv::Plane;
using gsv::ProxyGeometry;

namespace {

std::string error_message(const std::function<void()>& action) { return gsv::test::gsv_error_message(action); }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

struct Triangle {
    glm::dvec3 a, b, c;
    glm::dvec3 twice_area() const { return glm::cross(b - a, c - a); }
};

std::vector<Triangle> triangles_of(const MeshData& mesh) {
    std::vector<Triangle> result;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
        result.push_back({glm::dvec3(mesh.positions[mesh.indices[3 * t]]),
                          glm::dvec3(mesh.positions[mesh.indices[3 * t + 1]]),
                          glm::dvec3(mesh.positions[mesh.indices[3 * t + 2]])});
    return result;
}

// The divergence theorem with the field x / 3: the volume is the sum of the signed tetrahedra from the
// origin, which needs the mesh closed and wound outward.
double enclosed_volume(const MeshData& mesh) {
    double six_volume = 0.0;
    for (const Triangle& t : triangles_of(mesh)) six_volume += glm::dot(t.a, glm::cross(t.b, t.c));
    return six_volume / 6.0;
}

double surface_area(const MeshData& mesh) {
    double area = 0.0;
    for (const Triangle& t : triangles_of(mesh)) area += 0.5 * glm::length(t.twice_area());
    return area;
}

using EdgeKey = std::array<float, 6>;
EdgeKey edge_key(glm::vec3 from, glm::vec3 to) { return {from.x, from.y, from.z, to.x, to.y, to.z}; }

// Well formed, finite, no repeated corner, no zero-area or duplicate triangle, every edge used once in each
// direction (closed, consistently wound), and every triangle wound as its face normal says. The mesh may be
// empty. That the face normals point outward is check_outward's job, in double: a float32 sliver triangle
// 1e-5 wide has its normal tilted by up to 1e-2, enough to fool a test against a point inside.
void check_closed_mesh(const MeshData& mesh) {
    REQUIRE(mesh.normals.size() == mesh.positions.size());
    REQUIRE(mesh.texcoords.empty());
    REQUIRE(mesh.indices.size() % 3 == 0);
    for (std::uint32_t index : mesh.indices) REQUIRE(index < mesh.positions.size());
    if (mesh.indices.empty()) return;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        REQUIRE(finite(glm::dvec3(mesh.positions[i])));
        REQUIRE(std::abs(glm::length(mesh.normals[i]) - 1.0f) < 1e-6f);
    }

    std::map<EdgeKey, int> directed;
    std::map<std::array<float, 9>, int> seen;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        INFO("triangle " << t << " of " << mesh.triangle_count());
        const std::uint32_t* corner = &mesh.indices[3 * t];
        const glm::vec3 p[3] = {mesh.positions[corner[0]], mesh.positions[corner[1]], mesh.positions[corner[2]]};
        REQUIRE(p[0] != p[1]);
        REQUIRE(p[1] != p[2]);
        REQUIRE(p[2] != p[0]);
        const Triangle tri{glm::dvec3(p[0]), glm::dvec3(p[1]), glm::dvec3(p[2])};
        REQUIRE(glm::length(tri.twice_area()) > 0.0);
        REQUIRE(glm::dot(tri.twice_area(), glm::dvec3(mesh.normals[corner[0]])) > 0.0);
        std::array<glm::vec3, 3> sorted{p[0], p[1], p[2]};
        std::sort(sorted.begin(), sorted.end(), [](glm::vec3 u, glm::vec3 v) {
            return std::tie(u.x, u.y, u.z) < std::tie(v.x, v.y, v.z);
        });
        REQUIRE(++seen[{sorted[0].x, sorted[0].y, sorted[0].z, sorted[1].x, sorted[1].y, sorted[1].z, sorted[2].x,
                        sorted[2].y, sorted[2].z}] == 1);
        for (int k = 0; k < 3; ++k) ++directed[edge_key(p[k], p[(k + 1) % 3])];
    }
    for (const auto& [key, count] : directed) {
        INFO("edge (" << key[0] << ", " << key[1] << ", " << key[2] << ") -> (" << key[3] << ", " << key[4] << ", "
                      << key[5] << ")");
        REQUIRE(count == 1);
        const auto reverse = directed.find({key[3], key[4], key[5], key[0], key[1], key[2]});
        REQUIRE(reverse != directed.end());
        REQUIRE(reverse->second == 1);
    }
}

// Every face's loop winds as its normal says, and every vertex lies inside the face's plane: convex, with
// outward normals, up to the clipper's epsilon (points within it of a plane count as on it).
void check_outward(const gsv::ConvexPolyhedron& polyhedron) {
    const std::vector<glm::dvec3>& vertices = polyhedron.vertices();
    for (const auto& face : polyhedron.faces()) {
        INFO("face tagged " << face.tag);
        REQUIRE(polyhedron.face_area(face) > 0.0);
        glm::dvec3 centre(0.0);
        for (std::uint32_t v : face.loop) centre += vertices[v];
        centre /= double(face.loop.size());
        for (const glm::dvec3& v : vertices) REQUIRE(glm::dot(face.normal, v - centre) < 2 * gsv::kPlaneEpsilon);
    }
}

// Both checks on a proxy's mesh and polyhedron.
void check_proxy(const ProxyGeometry& proxy) {
    check_closed_mesh(proxy.mesh());
    check_outward(proxy.polyhedron());
}

// The faces of the polyhedron with a tag, and their total area.
double tagged_area(const ProxyGeometry& proxy, int tag, int* count = nullptr) {
    double area = 0.0;
    int faces = 0;
    for (const auto& face : proxy.polyhedron().faces())
        if (face.tag == tag) {
            area += proxy.polyhedron().face_area(face);
            ++faces;
        }
    if (count) *count = faces;
    return area;
}

// vol{x in [0,1]^3 : a.x <= d} for a with no zero component: the inclusion-exclusion of the corner simplices,
// sum over the cube's corners v of (-1)^|v| max(d - a.v, 0)^3 / (6 a1 a2 a3), after flipping x_i -> 1 - x_i
// where a_i < 0.
double cube_half_space_volume(glm::dvec3 a, double d) {
    for (int i = 0; i < 3; ++i)
        if (a[i] < 0) {
            d -= a[i];
            a[i] = -a[i];
        }
    double sum = 0.0;
    for (int v = 0; v < 8; ++v) {
        const glm::dvec3 corner(v & 1, (v >> 1) & 1, (v >> 2) & 1);
        const double reach = std::max(d - glm::dot(a, corner), 0.0);
        sum += ((v & 1) + ((v >> 1) & 1) + ((v >> 2) & 1)) % 2 ? -reach * reach * reach : reach * reach * reach;
    }
    return sum / (6.0 * a.x * a.y * a.z);
}

struct Random {
    std::uint64_t seed;
    std::uint64_t index = 0;
    double uniform(double lo = 0.0, double hi = 1.0) {
        return lo + (hi - lo) * gsv::unit_double(gsv::hash64(seed, index++));
    }
    glm::dvec3 point(double lo = 0.0, double hi = 1.0) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    glm::dvec3 direction() {
        while (true) {
            const glm::dvec3 d = point(-1.0, 1.0);
            const double length = glm::length(d);
            if (length > 0.1 && length <= 1.0) return d / length;
        }
    }
    // A plane through a point of the box with a random normal, sometimes of an odd length.
    Plane plane() {
        const glm::dvec3 normal = direction() * (uniform() < 0.3 ? uniform(0.01, 100.0) : 1.0);
        return gsv::plane_through(point(), normal);
    }
};

// Where the ray o + t d first hits one of the triangles at t > t_min, from either side (a ray through a
// shared edge may hit both): Moeller-Trumbore in double with the edges counted as inside.
std::optional<double> first_hit(const std::vector<Triangle>& triangles, glm::dvec3 o, glm::dvec3 d, double t_min) {
    std::optional<double> best;
    for (const Triangle& tri : triangles) {
        const glm::dvec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
        const glm::dvec3 p = glm::cross(d, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-300) continue;
        const glm::dvec3 s = o - tri.a;
        const double u = glm::dot(s, p) / det;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(d, q) / det;
        const double t = glm::dot(e2, q) / det;
        const double slack = -1e-9;
        if (u < slack || v < slack || u + v > 1.0 - slack || t <= t_min) continue;
        if (!best || t < *best) best = t;
    }
    return best;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// The box and its model-space placement

TEST_CASE("proxy: the unclipped box is 12 outward triangles whose positions are its texture coordinates", "[unit][proxy]") {
    const ProxyGeometry proxy;
    const MeshData mesh = proxy.mesh();
    REQUIRE(mesh.triangle_count() == 12);
    check_proxy(proxy);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 color = mesh.positions[i];
        for (int axis = 0; axis < 3; ++axis) CHECK((color[axis] == 0.0f || color[axis] == 1.0f));
        // An axis-aligned face: the normal points out through the side the vertex is on.
        const glm::vec3 n = mesh.normals[i];
        const int axis = std::abs(n.x) == 1.0f ? 0 : std::abs(n.y) == 1.0f ? 1 : 2;
        CHECK(std::abs(n[axis]) == 1.0f);
        CHECK(color[axis] == (n[axis] > 0 ? 1.0f : 0.0f));
    }
    CHECK(enclosed_volume(mesh) == Approx(1.0).epsilon(1e-12));
    CHECK(surface_area(mesh) == Approx(6.0).epsilon(1e-12));
    CHECK(proxy.polyhedron().volume() == Approx(1.0).epsilon(1e-12));
    CHECK(proxy.polyhedron().faces().size() == 6);
    CHECK(proxy.polyhedron().vertices().size() == 8);
}

TEST_CASE("proxy: the volume box maps texture coordinates linearly onto a centred box whose largest side is 2",
          "[unit][proxy]") {
    const glm::dvec3 extent(33 * 3.0, 41 * 3.0, 25 * 3.0);
    const gsv::VolumeBox box(extent);
    CHECK(box.size().y == 2.0);
    CHECK(box.size().x == Approx(2.0 * 33 / 41).epsilon(1e-15));
    CHECK(box.size().z == Approx(2.0 * 25 / 41).epsilon(1e-15));
    CHECK(box.physical_per_model() == Approx(61.5));
    CHECK(glm::length(box.model_from_texture(glm::dvec3(0.0)) + box.size() / 2.0) < 1e-15);
    CHECK(glm::length(box.model_from_texture(glm::dvec3(1.0)) - box.size() / 2.0) < 1e-15);
    CHECK(glm::length(box.model_from_texture(glm::dvec3(0.5))) == 0.0);

    // The proxy mesh's vertices land on the model box's corners through the model matrix, and the matrix,
    // the functions and their inverses agree everywhere.
    const glm::mat4 model = box.model_from_texture_matrix();
    const glm::mat4 inverse = box.texture_from_model_matrix();
    for (const glm::vec3& color : ProxyGeometry().mesh().positions) {
        const glm::dvec3 placed(model * glm::vec4(color, 1.0f));
        CHECK(glm::length(placed - box.model_from_texture(glm::dvec3(color))) < 1e-6);
        for (int axis = 0; axis < 3; ++axis) CHECK(std::abs(std::abs(placed[axis]) - box.size()[axis] / 2) < 1e-6);
    }
    Random random{7};
    for (int i = 0; i < 100; ++i) {
        const glm::dvec3 t = random.point(-1.0, 2.0);
        const glm::dvec3 m = box.model_from_texture(t);
        CHECK(glm::length(box.texture_from_model(m) - t) < 1e-14);
        CHECK(glm::length(glm::dvec3(inverse * glm::vec4(glm::vec3(m), 1.0f)) - t) < 1e-5);
        // A physical distance is the same measured in either space.
        const glm::dvec3 t2 = random.point();
        const glm::dvec3 physical = (t2 - t) * extent;
        CHECK(glm::length(box.model_from_texture(t2) - m) * box.physical_per_model() ==
              Approx(glm::length(physical)).epsilon(1e-12));
        CHECK(glm::length(box.texture_direction(box.model_from_texture(t2) - m) - (t2 - t)) < 1e-14);
    }

    // A model-space plane and its texture-space version keep the same points.
    for (int i = 0; i < 20; ++i) {
        const Plane model_plane = gsv::plane_through(random.point(-1.0, 1.0), random.direction());
        const Plane texture_plane = box.texture_plane(model_plane);
        CHECK(std::abs(glm::length(texture_plane.normal) - 1.0) < 1e-15);
        for (int k = 0; k < 50; ++k) {
            const glm::dvec3 t = random.point(-0.5, 1.5);
            const double model_side = model_plane.signed_distance(box.model_from_texture(t));
            if (std::abs(model_side) < 1e-9) continue;
            CHECK(texture_plane.keeps(t) == (model_side < 0));
        }
    }

    CHECK(contains(error_message([] { gsv::VolumeBox(glm::dvec3(1, 0, 1)); }), "extent (1, 0, 1)"));
    CHECK(contains(error_message([] { gsv::VolumeBox(glm::dvec3(1, -2, 1)); }), "-2"));
    CHECK(contains(error_message([] { gsv::VolumeBox(glm::dvec3(1, 1, INFINITY)); }), "inf"));
    CHECK(contains(error_message([] { gsv::VolumeBox(glm::dvec3(NAN, 1, 1)); }), "nan"));
}

// ---------------------------------------------------------------------------------------------------
// Clipping

TEST_CASE("proxy: an axis plane at 0.5 halves the volume and adds one cap of area 1", "[unit][proxy]") {
    for (int axis = 0; axis < 3; ++axis)
        for (const double sign : {1.0, -1.0}) {
            INFO("axis " << axis << " sign " << sign);
            glm::dvec3 normal(0.0);
            normal[axis] = sign;
            const ProxyGeometry proxy({Plane{normal, 0.5 * sign}});
            const MeshData mesh = proxy.mesh();
            check_proxy(proxy);
            CHECK(mesh.triangle_count() == 12);
            CHECK(enclosed_volume(mesh) == Approx(0.5).epsilon(1e-12));
            CHECK(proxy.polyhedron().volume() == Approx(0.5).epsilon(1e-12));
            int caps = 0;
            CHECK(tagged_area(proxy, gsv::kFirstClipTag, &caps) == Approx(1.0).epsilon(1e-12));
            CHECK(caps == 1);
            CHECK(proxy.polyhedron().faces().size() == 6);
            // The cut side of the box is gone and its opposite kept whole.
            CHECK(tagged_area(proxy, 2 * axis + (sign > 0 ? 1 : 0)) == 0.0);
            CHECK(tagged_area(proxy, 2 * axis + (sign > 0 ? 0 : 1)) == Approx(1.0).epsilon(1e-12));
            for (const glm::vec3& p : mesh.positions)
                CHECK(sign * p[axis] <= sign * 0.5f);
        }
}

TEST_CASE("proxy: oblique planes through the centre halve the volume", "[unit][proxy]") {
    for (const glm::dvec3& normal : {glm::dvec3(1, 1, 1), glm::dvec3(1, 2, 3), glm::dvec3(-0.3, 0.7, 0.2),
                                    glm::dvec3(1, -1, 0), glm::dvec3(0, 5, -1e-3)}) {
        INFO("normal (" << normal.x << ", " << normal.y << ", " << normal.z << ")");
        const ProxyGeometry proxy({gsv::plane_through(glm::dvec3(0.5), normal)});
        const MeshData mesh = proxy.mesh();
        check_proxy(proxy);
        // The cube is symmetric about its centre, so any plane through the centre halves it.
        CHECK(enclosed_volume(mesh) == Approx(0.5).epsilon(1e-7));
        CHECK(proxy.polyhedron().volume() == Approx(0.5).epsilon(1e-12));
    }
    // The (1, 1, 1) cut is a regular hexagon with sides sqrt(2) / 2.
    const ProxyGeometry hexagon({gsv::plane_through(glm::dvec3(0.5), glm::dvec3(1, 1, 1))});
    int caps = 0;
    CHECK(tagged_area(hexagon, gsv::kFirstClipTag, &caps) == Approx(3.0 * std::sqrt(3.0) / 4.0).epsilon(1e-12));
    CHECK(caps == 1);
    for (const auto& face : hexagon.polyhedron().faces())
        if (face.tag == gsv::kFirstClipTag) CHECK(face.loop.size() == 6);
}

TEST_CASE("proxy: planes through a vertex, along an edge or on a face keep, cut or remove exactly", "[unit][proxy]") {
    struct Case {
        const char* name;
        Plane plane;
        double volume;
        int faces;  // 0: empty
    };
    const Case cases[] = {
        {"through three vertices, keeping the corner tetrahedron", {{1, 1, 1}, 1}, 1.0 / 6, 4},
        {"through the other three vertices", {{1, 1, 1}, 2}, 5.0 / 6, 7},
        {"touching the vertex (1,1,1) from outside", {{1, 1, 1}, 3}, 1.0, 6},
        {"keeping only the vertex (1,1,1)", {{-1, -1, -1}, -3}, 0.0, 0},
        {"through the vertex (0,0,0) alone", {{3, 1, -2}, 0}, cube_half_space_volume({3, 1, -2}, 0), 5},
        {"within the epsilon of three vertices", {{1, 1, 1}, 1 + 1e-9}, 1.0 / 6, 4},
        {"through two opposite edges", {{1, 1, 0}, 1}, 0.5, 5},
        {"through the diagonal edges", {{1, -1, 0}, 0}, 0.5, 5},
        {"touching an edge from outside", {{1, 1, 0}, 2}, 1.0, 6},
        {"keeping only an edge", {{-1, -1, 0}, -2}, 0.0, 0},
        {"on the face x = 1 from inside", {{1, 0, 0}, 1}, 1.0, 6},
        {"on the face x = 1 from outside", {{-1, 0, 0}, -1}, 0.0, 0},
        {"on the face x = 0, keeping only it", {{1, 0, 0}, 0}, 0.0, 0},
        {"on the face x = 0 from inside", {{-1, 0, 0}, 0}, 1.0, 6},
        {"within the epsilon of the face z = 1", {{0, 0, 1}, 1 - 1e-7}, 1.0, 6},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const ProxyGeometry proxy({c.plane});
        const MeshData mesh = proxy.mesh();
        check_proxy(proxy);
        CHECK(proxy.polyhedron().faces().size() == std::size_t(c.faces));
        CHECK(proxy.empty() == (c.faces == 0));
        CHECK(enclosed_volume(mesh) == Approx(c.volume).epsilon(1e-6).margin(1e-12));
        CHECK(proxy.polyhedron().volume() == Approx(c.volume).epsilon(1e-6).margin(1e-12));
        if (c.volume == 1.0) CHECK(mesh.triangle_count() == 12);
    }
    // The corner tetrahedron's cap is the equilateral triangle with sides sqrt(2).
    CHECK(tagged_area(ProxyGeometry({Plane{{1, 1, 1}, 1}}), gsv::kFirstClipTag) ==
          Approx(std::sqrt(3.0) / 2).epsilon(1e-12));
    CHECK(tagged_area(ProxyGeometry({Plane{{1, 1, 0}, 1}}), gsv::kFirstClipTag) == Approx(std::sqrt(2.0)).epsilon(1e-12));
}

TEST_CASE("proxy: a plane that keeps everything changes nothing and one that removes everything leaves an empty mesh",
          "[unit][proxy]") {
    for (const Plane& plane : {Plane{{1, 0, 0}, 5}, Plane{{1, 2, 3}, 6 + 1e-3}, Plane{{-1, -1, -1}, 0}}) {
        const ProxyGeometry proxy({plane});
        CHECK(proxy.mesh().triangle_count() == 12);
        CHECK(proxy.polyhedron().volume() == Approx(1.0).epsilon(1e-12));
        CHECK(proxy.contains(glm::dvec3(0.5)));
    }
    for (const Plane& plane : {Plane{{1, 0, 0}, -1}, Plane{{1, 2, 3}, -1e-3}, Plane{{-1, -1, -1}, -3.5}}) {
        const ProxyGeometry proxy({plane, Plane{{0, 0, 1}, 0.5}});  // a later plane cuts nothing
        CHECK(proxy.empty());
        const MeshData mesh = proxy.mesh();
        CHECK(mesh.positions.empty());
        CHECK(mesh.indices.empty());
        CHECK(proxy.polyhedron().volume() == 0.0);
        CHECK_FALSE(proxy.contains(glm::dvec3(0.5)));
        CHECK(proxy.near_cap(gsv::near_plane(glm::dvec3(0.5), {0, 0, 1}, 0.01)).indices.empty());
    }
}

TEST_CASE("proxy: several planes cut the volume to its analytic value in any order", "[unit][proxy]") {
    const std::vector<Plane> slab = {{{-1, 0, 0}, -0.2}, {{1, 0, 0}, 0.7}, {{0, 1, 0}, 0.6}, {{0, 0, -1}, -0.1}};
    std::vector<Plane> order = slab;
    std::sort(order.begin(), order.end(), [](const Plane& a, const Plane& b) { return a.offset < b.offset; });
    do {
        const ProxyGeometry proxy(order);
        check_proxy(proxy);
        CHECK(enclosed_volume(proxy.mesh()) == Approx(0.5 * 0.6 * 0.9).epsilon(1e-7));
        CHECK(proxy.polyhedron().faces().size() == 6);
    } while (std::next_permutation(order.begin(), order.end(),
                                   [](const Plane& a, const Plane& b) { return a.offset < b.offset; }));

    // The corner tetrahedron less the small one beyond x = 1/2: 1/6 - (1/2)^3 / 6.
    const ProxyGeometry cut({Plane{{1, 1, 1}, 1}, Plane{{1, 0, 0}, 0.5}});
    check_proxy(cut);
    CHECK(enclosed_volume(cut.mesh()) == Approx(7.0 / 48).epsilon(1e-7));

    // Six planes around [0.1, 0.9]^3 replace every side of the box.
    std::vector<Plane> inner;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 n(0.0);
        n[axis] = 1;
        inner.push_back({n, 0.9});
        inner.push_back({-n, -0.1});
    }
    const ProxyGeometry cube(inner);
    check_proxy(cube);
    CHECK(enclosed_volume(cube.mesh()) == Approx(0.512).epsilon(1e-7));
    for (int tag = 0; tag < 6; ++tag) CHECK(tagged_area(cube, tag) == 0.0);
    for (int i = 0; i < 6; ++i) CHECK(tagged_area(cube, gsv::kFirstClipTag + i) == Approx(0.64).epsilon(1e-12));

    // Two half-spaces that do not overlap inside the box.
    CHECK(ProxyGeometry({Plane{{1, 0, 0}, 0.3}, Plane{{-1, 0, 0}, -0.6}}).empty());
}

TEST_CASE("proxy: thin slivers stay closed, and one thinner than the epsilon is removed", "[unit][proxy]") {
    // A slab 2e-5 thick.
    const ProxyGeometry slab({Plane{{1, 0, 0}, 0.5 + 1e-5}, Plane{{-1, 0, 0}, -(0.5 - 1e-5)}});
    check_proxy(slab);
    CHECK(enclosed_volume(slab.mesh()) == Approx(2e-5).epsilon(5e-3));
    CHECK(slab.polyhedron().volume() == Approx(2e-5).epsilon(1e-9));

    // A wedge between x <= 1/2 and x >= 1/2 - 1e-4 y, meeting along the edge x = 1/2, y = 0.
    const ProxyGeometry wedge({Plane{{1, 0, 0}, 0.5}, Plane{{-1, -1e-4, 0}, -0.5}});
    check_proxy(wedge);
    CHECK(wedge.polyhedron().volume() == Approx(0.5e-4).epsilon(1e-9));
    CHECK(enclosed_volume(wedge.mesh()) == Approx(0.5e-4).epsilon(5e-3));

    // Two planes crossing at a shallow angle inside the box, leaving a thin wedge near a box edge.
    const ProxyGeometry corner({Plane{{1, 1, 0}, 0.02}, Plane{{-1, -1.001, 0}, -0.0199}});
    check_proxy(corner);
    CHECK(corner.polyhedron().volume() > 0.0);

    // Thinner than kPlaneEpsilon: documented to vanish rather than produce float-degenerate triangles.
    const ProxyGeometry too_thin({Plane{{1, 0, 0}, 0.5 + 2e-7}, Plane{{-1, 0, 0}, -(0.5 - 2e-7)}});
    CHECK(too_thin.empty());
    CHECK(too_thin.mesh().indices.empty());
}

TEST_CASE("proxy: non-unit normals are made unit length and a zero normal is an error naming the plane", "[unit][proxy]") {
    const ProxyGeometry reference({Plane{{1, 0, 0}, 0.5}});
    for (const Plane& plane : {Plane{{2, 0, 0}, 1}, Plane{{1e-200, 0, 0}, 0.5e-200}, Plane{{1e200, 0, 0}, 0.5e200},
                               Plane{{0.25, 0, 0}, 0.125}}) {
        const ProxyGeometry proxy({plane});
        REQUIRE(proxy.clip_planes().size() == 1);
        CHECK(proxy.clip_planes()[0].normal == glm::dvec3(1, 0, 0));
        CHECK(proxy.clip_planes()[0].offset == 0.5);
        CHECK(proxy.mesh().positions == reference.mesh().positions);
    }
    const Plane tilted = gsv::normalized(Plane{{3, 4, 0}, 10}, "tilted");
    CHECK(glm::length(tilted.normal - glm::dvec3(0.6, 0.8, 0)) < 1e-15);
    CHECK(tilted.offset == Approx(2.0).epsilon(1e-15));

    const std::string zero = error_message([] { ProxyGeometry({Plane{{1, 0, 0}, 0.5}, Plane{{0, 0, 0}, 1}}); });
    CHECK(contains(zero, "clip plane 1 has a zero normal"));
    CHECK(contains(error_message([] { ProxyGeometry({Plane{{0, NAN, 1}, 0.5}}); }), "clip plane 0"));
    CHECK(contains(error_message([] { ProxyGeometry({Plane{{0, 0, 1}, INFINITY}}); }), "offset inf"));
    CHECK(contains(error_message([] { gsv::ray_proxy_span({0, 0, 0}, {1, 0, 0}, {Plane{}, Plane{{0, 0, 0}, 1}}); }),
                   "clip plane 1 has a zero normal"));
    // The clipper itself insists on a unit normal rather than quietly using a scaled epsilon.
    CHECK(contains(error_message([] { gsv::ConvexPolyhedron::unit_cube().clip(Plane{{2, 0, 0}, 1}, 9); }),
                   "unit normal"));
}

TEST_CASE("proxy: random plane sets give closed outward meshes with volume in 0 to 1 that agree with sampling",
          "[unit][proxy]") {
    Random random{20240607};
    int non_empty = 0, cut = 0;
    for (int set = 0; set < 300; ++set) {
        std::vector<Plane> planes;
        const int count = 1 + set % 6;
        for (int i = 0; i < count; ++i) planes.push_back(random.plane());
        INFO("set " << set << " with " << count << " planes");
        const ProxyGeometry proxy(planes);
        const MeshData mesh = proxy.mesh();
        check_proxy(proxy);
        if (proxy.empty()) continue;
        ++non_empty;
        const double volume = enclosed_volume(mesh);
        CHECK(volume > 0.0);
        CHECK(volume <= 1.0 + 1e-6);
        if (volume < 1.0 - 1e-6) ++cut;
        CHECK(volume == Approx(proxy.polyhedron().volume()).epsilon(1e-5).margin(1e-6));
        // Every vertex lies in the exact region, up to the clipper's epsilon.
        for (const glm::dvec3& v : proxy.polyhedron().vertices()) {
            for (int axis = 0; axis < 3; ++axis) CHECK((v[axis] >= -1e-12 && v[axis] <= 1.0 + 1e-12));
            for (const Plane& plane : proxy.clip_planes()) CHECK(plane.signed_distance(v) <= 2 * gsv::kPlaneEpsilon);
        }
        // Against the fraction of random points the exact test keeps (standard deviation below 0.0036).
        if (set < 60) {
            const int samples = 20000;
            int inside = 0;
            for (int k = 0; k < samples; ++k) inside += proxy.contains(random.point());
            CHECK(volume == Approx(double(inside) / samples).margin(0.02));
        }
    }
    CHECK(non_empty > 100);
    CHECK(cut > 100);
}

TEST_CASE("proxy: planes through earlier corners or nearly parallel to earlier planes still give closed meshes",
          "[unit][proxy]") {
    // The epsilon's hard cases on purpose: each plane passes within 1e-10 .. 1e-4 of a corner the earlier
    // planes made, or through two of them, or is an earlier plane tilted and shifted by 1e-9 .. 1e-3,
    // either way round. Bodies thinner than the epsilon vanish; the rest must stay closed and outward.
    Random random{4242};
    int non_empty = 0;
    for (int set = 0; set < 500; ++set) {
        std::vector<Plane> planes;
        ProxyGeometry current;
        for (int i = 0; i < 1 + set % 8; ++i) {
            const std::vector<glm::dvec3>& corners = current.polyhedron().vertices();
            const auto corner = [&] { return corners[std::size_t(random.uniform() * double(corners.size()))]; };
            const double tiny = std::pow(10.0, random.uniform(-10.0, -4.0)) * (random.uniform() < 0.5 ? -1 : 1);
            const double kind = random.uniform();
            Plane plane = random.plane();
            if (kind < 0.3 && !corners.empty()) {
                plane = gsv::plane_through(corner(), random.direction());
                plane.offset += tiny;
            } else if (kind < 0.5 && !corners.empty()) {
                const glm::dvec3 a = corner(), b = corner();
                const glm::dvec3 normal = glm::cross(b - a, random.direction());
                plane = gsv::plane_through(a, glm::length(normal) > 1e-3 ? normal : random.direction());
                plane.offset += tiny;
            } else if (kind < 0.7 && !planes.empty()) {
                const Plane earlier = current.clip_planes()[std::size_t(random.uniform() * double(planes.size()))];
                const double flip = random.uniform() < 0.5 ? 1.0 : -1.0;
                plane = Plane{flip * (earlier.normal + std::abs(tiny) * 10 * random.direction()),
                              flip * earlier.offset + tiny * 10};
            }
            planes.push_back(plane);
            current = ProxyGeometry(planes);
        }
        INFO("set " << set);
        check_proxy(current);
        if (current.empty()) continue;
        ++non_empty;
        CHECK(enclosed_volume(current.mesh()) == Approx(current.polyhedron().volume()).epsilon(1e-5).margin(1e-6));
    }
    CHECK(non_empty > 100);
}

// ---------------------------------------------------------------------------------------------------
// The near-plane cap and the camera inside

TEST_CASE("proxy: a camera at the centre gets a near cap that is the box cross-section", "[unit][proxy]") {
    const gsv::VolumeBox box({33 * 3.0, 41 * 3.0, 25 * 3.0});
    const ProxyGeometry proxy;
    const glm::dvec3 eye_texture = box.texture_from_model(glm::dvec3(0.0));
    CHECK(proxy.contains(eye_texture));
    const double near = 0.01;  // model units
    for (int axis = 0; axis < 3; ++axis)
        for (const double sign : {1.0, -1.0}) {
            INFO("looking along axis " << axis << " sign " << sign);
            glm::dvec3 forward(0.0);
            forward[axis] = sign;
            const Plane near_texture = box.texture_plane(gsv::near_plane(glm::dvec3(0.0), forward, near));
            const MeshData cap = proxy.near_cap(near_texture);
            REQUIRE(cap.triangle_count() >= 2);
            CHECK(cap.texcoords.empty());
            CHECK(surface_area(cap) == Approx(1.0).epsilon(1e-6));
            // On the near plane moved kNearCapOffset further from the camera, inside the box.
            const double expected = 0.5 + sign * (near / box.size()[axis] + gsv::kNearCapOffset);
            const glm::dvec3 forward_texture = glm::normalize(box.texture_direction(forward));
            for (const glm::vec3& color : cap.positions) {
                CHECK(std::abs(color[axis] - expected) < 1e-6);
                for (int other = 0; other < 3; ++other) CHECK((color[other] >= 0.0f && color[other] <= 1.0f));
            }
            // Counter-clockwise seen from the camera, so it survives culling with the front faces.
            for (const Triangle& t : triangles_of(cap)) {
                CHECK(glm::dot(t.twice_area(), -forward_texture) > 0.0);
                CHECK(glm::length(t.twice_area()) > 0.0);
            }
        }
    // With a clip plane the cap is the cross-section of what is left.
    const ProxyGeometry half({Plane{{1, 0, 0}, 0.5}});
    const Plane near_texture = box.texture_plane(gsv::near_plane(glm::dvec3(0.0), {0, 0, 1}, near));
    CHECK(surface_area(half.near_cap(near_texture)) == Approx(0.5).epsilon(1e-6));
    CHECK(surface_area(half.near_cap(near_texture, 0.0)) == Approx(0.5).epsilon(1e-6));
    CHECK(contains(error_message([&] { half.near_cap(near_texture, -1e-3); }), "offset -0.001"));
    CHECK(contains(error_message([&] { half.near_cap(Plane{{0, 0, 0}, 1}); }), "near plane has a zero normal"));
    CHECK(contains(error_message([] { gsv::near_plane({0, 0, 0}, {0, 0, 0}, 0.1); }), "forward (0, 0, 0)"));
}

TEST_CASE("proxy: the near cap is empty when the near plane misses the proxy, and present when it reaches in",
          "[unit][proxy]") {
    const gsv::VolumeBox box({64.0, 64.0, 128.0});
    const ProxyGeometry proxy;
    const auto cap_for = [&](glm::dvec3 eye, glm::dvec3 forward, double near) {
        return proxy.near_cap(box.texture_plane(gsv::near_plane(eye, forward, near)));
    };
    // Far outside, looking at the box: the near plane is in front of the camera but before the box.
    CHECK_FALSE(proxy.contains(box.texture_from_model({0, 0, -3})));
    CHECK(cap_for({0, 0, -3}, {0, 0, 1}, 0.1).indices.empty());
    // Outside looking away: the whole box is behind the near plane.
    CHECK(cap_for({0, 0, -3}, {0, 0, -1}, 0.1).indices.empty());
    // Just outside the face z = -1, but the near plane at 0.1 reaches 0.05 into the box: a cap is needed.
    const glm::dvec3 eye(0.0, 0.0, -1.05);
    CHECK_FALSE(proxy.contains(box.texture_from_model(eye)));
    const MeshData reaching = cap_for(eye, {0, 0, 1}, 0.1);
    CHECK(surface_area(reaching) == Approx(1.0).epsilon(1e-6));

    // The inside test is exact, with the boundary inside.
    const ProxyGeometry clipped({Plane{{1, 0, 0}, 0.5}});
    CHECK(clipped.contains({0.5, 0.5, 0.5}));
    CHECK(clipped.contains({0.0, 0.0, 0.0}));
    CHECK(clipped.contains({0.5, 1.0, 0.0}));
    CHECK_FALSE(clipped.contains({std::nextafter(0.5, 1.0), 0.5, 0.5}));
    CHECK_FALSE(clipped.contains({0.25, -1e-300, 0.5}));
    CHECK_FALSE(clipped.contains({0.25, 0.5, NAN}));
    CHECK_FALSE(clipped.contains({0.75, 0.5, 0.5}));
    // Oblique planes are taken as given, not with rounded unit normals, by contains and ray_span alike.
    const ProxyGeometry oblique({Plane{{1, 1, 0}, 1}});
    CHECK(oblique.contains({0.25, 0.75, 0.5}));
    CHECK_FALSE(oblique.contains({0.25, 0.75 + 1e-15, 0.5}));
    const std::optional<gsv::RaySpan> along = oblique.ray_span({0.25, 0.75, 0.5}, {-1, 1, 0});
    REQUIRE(along);
    CHECK(along->entry == -0.75);
    CHECK(along->exit == 0.25);
}

TEST_CASE("proxy: front faces plus the near cap give the exact entry points for a camera inside the volume",
          "[unit][proxy]") {
    // What the GL side draws into the entry image, rasterized on the CPU: per pixel ray, the nearest
    // front-facing proxy triangle beyond the near plane, or the cap. It must start each ray where the exact
    // span does, or at the near plane where the span starts behind it.
    Random random{99};
    int inside = 0, checked = 0, from_cap = 0;
    for (int scene = 0; scene < 12; ++scene) {
        std::vector<Plane> planes;
        for (int i = 0; i < scene % 3; ++i)
            planes.push_back(gsv::plane_through(random.point(0.6, 0.9), random.direction()));
        const ProxyGeometry proxy(planes);
        if (proxy.empty()) continue;
        const glm::dvec3 eye = random.point(0.2, 0.8);
        const glm::dvec3 forward = random.direction();
        const double near = 0.01;
        const Plane near_texture = gsv::near_plane(eye, forward, near);
        const std::vector<Triangle> mesh = triangles_of(proxy.mesh());
        const std::vector<Triangle> cap = triangles_of(proxy.near_cap(near_texture));
        INFO("scene " << scene << (proxy.contains(eye) ? ", eye inside" : ", eye outside"));
        inside += proxy.contains(eye);
        for (int ray = 0; ray < 200; ++ray) {
            const glm::dvec3 d = glm::normalize(forward + 0.6 * random.direction());
            const double t_near = near / glm::dot(d, forward);  // where the ray crosses the near plane
            std::vector<Triangle> front;
            for (const Triangle& t : mesh)
                if (glm::dot(t.twice_area(), d) < 0) front.push_back(t);
            std::optional<double> drawn = first_hit(front, eye, d, t_near);
            const std::optional<double> capped = first_hit(cap, eye, d, t_near);
            if (capped && (!drawn || *capped < *drawn)) {  // GL_LESS
                drawn = capped;
                ++from_cap;
            }
            const std::optional<gsv::RaySpan> span = proxy.ray_span(eye, d);
            const bool visible = span && span->exit > t_near;
            // Rays within a hair of the proxy's silhouette may go either way.
            if (span && std::abs(span->exit - std::max(span->entry, t_near)) < 1e-3) continue;
            REQUIRE(drawn.has_value() == visible);
            ++checked;
            if (visible) {
                const double expected = std::max(span->entry, t_near);
                CHECK(std::abs(*drawn - expected) < 2 * gsv::kNearCapOffset + 1e-6);
            }
        }
    }
    CHECK(inside >= 6);
    CHECK(checked > 2000);
    CHECK(from_cap > 1000);
}

// ---------------------------------------------------------------------------------------------------
// The exact ray reference

TEST_CASE("proxy: ray spans agree with brute-force marching for random rays and planes", "[unit][proxy]") {
    Random random{31337};
    int hits = 0;
    for (int ray = 0; ray < 300; ++ray) {
        std::vector<Plane> planes;
        for (int i = 0; i < ray % 4; ++i) planes.push_back(random.plane());
        const ProxyGeometry proxy(planes);
        const glm::dvec3 origin = random.point(-1.0, 2.0);
        // Half the rays aimed at a point of the box, so that many hit; all of them of random length.
        const glm::dvec3 aim = ray % 2 ? glm::normalize(random.point() - origin) : random.direction();
        const glm::dvec3 direction = aim * random.uniform(0.5, 2.0);
        INFO("ray " << ray);
        const std::optional<gsv::RaySpan> span = gsv::ray_proxy_span(origin, direction, planes);
        // March the line in steps of h over t in [-12, 12]: from [-1, 2]^3 with |direction| >= 0.5, the box is
        // at most sqrt(27) / 0.5 < 10.4 away.
        const double h = 1e-3;
        std::optional<double> first, last;
        for (int k = -12000; k <= 12000; ++k) {
            const double t = k * h;
            if (proxy.contains(origin + t * direction)) {
                if (!first) first = t;
                last = t;
            }
        }
        if (first) {
            REQUIRE(span);
            ++hits;
            CHECK(std::isfinite(span->entry));
            CHECK(span->entry <= *first + 1e-12);
            CHECK(span->entry > *first - h);
            CHECK(span->exit >= *last - 1e-12);
            CHECK(span->exit < *last + h);
        } else if (span) {
            // Only a span shorter than the step can fall between the samples.
            CHECK(span->exit - span->entry < h);
        }
    }
    CHECK(hits > 60);
}

TEST_CASE("proxy: ray spans with a direction component of exactly 0 and the origin on a slab plane", "[unit][proxy]") {
    const auto span = [](glm::dvec3 o, glm::dvec3 d, std::vector<Plane> planes = {}) {
        return gsv::ray_proxy_span(o, d, planes);
    };
    // On the face x = 0, running along it: 0 * inf would be NaN; the boundary counts as inside.
    auto s = span({0, 0.5, 0.25}, {0, 0, 1});
    REQUIRE(s);
    CHECK(s->entry == -0.25);
    CHECK(s->exit == 0.75);
    s = span({1, 1, 0.5}, {0, 0, -2});  // on the edge x = y = 1
    REQUIRE(s);
    CHECK(s->entry == -0.25);
    CHECK(s->exit == 0.25);
    // A hair outside the face: parallel and outside, so it misses.
    CHECK_FALSE(span({std::nextafter(1.0, 2.0), 0.5, 0.5}, {0, 1, 0}));
    CHECK_FALSE(span({-0.0 - 1e-300, 0.5, 0.5}, {0, 0, 1}));
    CHECK(span({-0.0, 0.5, 0.5}, {0, 0, 1}));
    // The same for a clip plane: on it and parallel is inside, just beyond it is not.
    s = span({0.5, 0.5, 0.5}, {0, 1, 0}, {Plane{{2, 0, 0}, 1}});
    REQUIRE(s);
    CHECK(s->entry == -0.5);
    CHECK(s->exit == 0.5);
    CHECK_FALSE(span({std::nextafter(0.5, 1.0), 0.5, 0.5}, {0, 1, 0}, {Plane{{2, 0, 0}, 1}}));
    // An oblique clip plane with the ray inside it: exactly parallel, exactly on it.
    s = span({0.25, 0.75, 0.0}, {1, -1, 0}, {Plane{{1, 1, 0}, 1}});
    REQUIRE(s);
    CHECK(s->entry == -0.25);
    CHECK(s->exit == 0.75);
    // Two zero components, the origin on two slab planes at once, the third from outside.
    s = span({0, 1, -3}, {0, 0, 0.5});
    REQUIRE(s);
    CHECK(s->entry == 6.0);
    CHECK(s->exit == 8.0);
    // A vanishing but non-zero component: infinities, never NaN.
    s = span({0.5, 0.5, 0.5}, {1e-320, 0, 0});
    REQUIRE(s);
    CHECK_FALSE(std::isnan(s->entry));
    CHECK_FALSE(std::isnan(s->exit));
    CHECK(s->entry < 0.0);
    CHECK(s->exit > 0.0);
}

TEST_CASE("proxy: a ray along an edge, grazing an edge or a corner, and rays that miss", "[unit][proxy]") {
    const auto span = [](glm::dvec3 o, glm::dvec3 d, std::vector<Plane> planes = {}) {
        return gsv::ray_proxy_span(o, d, planes);
    };
    // Along the edge x = y = 0.
    auto s = span({0, 0, -1}, {0, 0, 1});
    REQUIRE(s);
    CHECK(s->entry == 1.0);
    CHECK(s->exit == 2.0);
    // Touching the edge x = 1, z = 0 at one point: entry == exit.
    s = span({0, 0.5, -1}, {1, 0, 1});
    REQUIRE(s);
    CHECK(s->entry == 1.0);
    CHECK(s->exit == 1.0);
    // Touching the corner (1, 1, 1).
    s = span({2, 2, 0}, {-1, -1, 1});
    REQUIRE(s);
    CHECK(s->entry == 1.0);
    CHECK(s->exit == 1.0);
    // Touching the corner (1, 0, 0) that the plane x + y + z <= 1 leaves, while lying in that plane.
    s = span({1, -1, 1}, {0, 1, -1}, {Plane{{1, 1, 1}, 1}});
    REQUIRE(s);
    CHECK(s->entry == 1.0);
    CHECK(s->exit == 1.0);
    // Misses: beside the box, past a corner, and cut away by a plane.
    CHECK_FALSE(span({2, 2, 2}, {1, 0, 0}));
    CHECK_FALSE(span({2, 2, 0}, {-1, -1, 1.0 + 1e-12}));
    CHECK_FALSE(span({0.9, -1, 0.5}, {0, 1, 0}, {Plane{{1, 0, 0}, 0.5}}));
    CHECK_FALSE(span({0.5, 0.5, 0.5}, {1, 1, 1}, {Plane{{1, 0, 0}, -0.5}}));
    // Bad rays are refused, naming them.
    CHECK(contains(error_message([&] { span({0, 0, 0}, {0, 0, 0}); }), "along (0, 0, 0)"));
    CHECK(contains(error_message([&] { span({NAN, 0, 0}, {1, 0, 0}); }), "from (nan, 0, 0)"));
    CHECK(contains(error_message([&] { span({0, 0, 0}, {INFINITY, 0, 0}); }), "along (inf, 0, 0)"));
}
