#include "catch.hpp"
#include "gl_fixture.h"

#include "common/core/error.h"
#include "common/scene/mesh_data.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <utility>
#include <fstream>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

namespace fs = std::filesystem;
using gsv::MeshData;

namespace {

// Catch2 v2 and v3 name their substring matcher differently, so messages are checked by hand.
std::string error_message(const std::function<void()>& action) {
    try {
        action();
    } catch (const gsv::Error& error) {
        return error.what();
    }
    return "(no gsv::Error thrown)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(glm::vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

void check_well_formed(const MeshData& mesh) {
    REQUIRE(mesh.normals.size() == mesh.positions.size());
    REQUIRE((mesh.texcoords.empty() || mesh.texcoords.size() == mesh.positions.size()));
    REQUIRE(mesh.indices.size() % 3 == 0);
    for (std::uint32_t index : mesh.indices) REQUIRE(index < mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        INFO("vertex " << i);
        REQUIRE(finite(mesh.positions[i]));
        REQUIRE(finite(mesh.normals[i]));
        REQUIRE(std::abs(glm::length(mesh.normals[i]) - 1.0f) < 1e-5f);
    }
    for (glm::vec2 uv : mesh.texcoords) REQUIRE(finite(uv));
}

// Calls `check(face_normal, a, b, c, triangle)` for every triangle with a usable geometric normal.
template <typename Check>
int for_each_proper_triangle(const MeshData& mesh, Check check) {
    int checked = 0;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const glm::vec3 a = mesh.positions[mesh.indices[3 * t]];
        const glm::vec3 b = mesh.positions[mesh.indices[3 * t + 1]];
        const glm::vec3 c = mesh.positions[mesh.indices[3 * t + 2]];
        const glm::vec3 face = glm::cross(b - a, c - a);
        if (glm::length(face) < 1e-9f) continue;
        check(face, a, b, c, t);
        ++checked;
    }
    return checked;
}

// A scratch directory removed again at the end of the test.
struct TempDir {
    fs::path path;
    TempDir() {
        static std::atomic<int> counter{0};
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        path = fs::temp_directory_path() /
               ("gsv_mesh_data_" + std::to_string(stamp) + "_" + std::to_string(counter++));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path file = path / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
};

using gsv::test::source_root;

}  // namespace

TEST_CASE("mesh_data: uv sphere normals are unit and equal position/radius, without NaN at the poles", "[unit]") {
    for (const auto& [slices, stacks, radius] : {std::tuple{3, 2, 1.0f}, std::tuple{24, 12, 2.5f},
                                                 std::tuple{7, 5, 0.01f}, std::tuple{64, 33, 100.0f}}) {
        INFO("slices " << slices << " stacks " << stacks << " radius " << radius);
        const MeshData sphere = gsv::make_uv_sphere(slices, stacks, radius);
        check_well_formed(sphere);
        REQUIRE(sphere.texcoords.size() == sphere.positions.size());
        int poles = 0;
        for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
            const glm::vec3 expected = sphere.positions[i] / radius;
            REQUIRE(std::abs(glm::length(sphere.normals[i]) - 1.0f) < 1e-6f);
            REQUIRE(glm::length(sphere.normals[i] - expected) < 1e-6f);
            if (std::abs(sphere.normals[i].y) == 1.0f) ++poles;
            REQUIRE(sphere.texcoords[i].x >= 0.0f);
            REQUIRE(sphere.texcoords[i].x <= 1.0f);
            REQUIRE(sphere.texcoords[i].y >= 0.0f);
            REQUIRE(sphere.texcoords[i].y <= 1.0f);
            // v is the latitude fraction: 0 at the south pole, 1 at the north pole.
            REQUIRE(std::abs(sphere.texcoords[i].y - (std::asin(glm::clamp(expected.y, -1.0f, 1.0f)) /
                                                          glm::pi<float>() + 0.5f)) < 1e-5f);
        }
        REQUIRE(poles == 2 * slices);
    }
}

TEST_CASE("mesh_data: uv sphere and torus have the documented counts", "[unit]") {
    const MeshData sphere = gsv::make_uv_sphere(16, 8);
    CHECK(sphere.positions.size() == 2 * 16 + 7 * 17);
    CHECK(sphere.triangle_count() == 2 * 16 * 7);
    const MeshData smallest = gsv::make_uv_sphere(3, 2);
    CHECK(smallest.positions.size() == 2 * 3 + 1 * 4);
    CHECK(smallest.triangle_count() == 6);

    const MeshData torus = gsv::make_torus(32, 12, 1.0f, 0.3f);
    CHECK(torus.positions.size() == 33 * 13);
    CHECK(torus.triangle_count() == 2 * 32 * 12);
    CHECK(torus.texcoords.size() == torus.positions.size());
    // The counts without the meshes (lab 01's work per frame) are the built meshes' own.
    for (const auto& [around, other] : {std::pair{3, 2}, std::pair{16, 8}, std::pair{64, 32}, std::pair{7, 3}}) {
        INFO(around << " x " << other);
        CHECK(gsv::uv_sphere_triangle_count(around, other) == gsv::make_uv_sphere(around, other).triangle_count());
        if (other >= 3)
            CHECK(gsv::torus_triangle_count(around, other) == gsv::make_torus(around, other, 1.0f, 0.3f).triangle_count());
    }
}

TEST_CASE("mesh_data: sphere and torus triangles wind counter-clockwise seen from outside", "[unit]") {
    const MeshData sphere = gsv::make_uv_sphere(20, 10, 3.0f);
    const int sphere_checked = for_each_proper_triangle(sphere, [&](glm::vec3 face, glm::vec3 a, glm::vec3 b,
                                                                    glm::vec3 c, std::size_t t) {
        INFO("sphere triangle " << t);
        REQUIRE(glm::dot(face, (a + b + c) / 3.0f) > 0.0f);
    });
    CHECK(sphere_checked == static_cast<int>(sphere.triangle_count()));  // no degenerate cap triangles

    // On a torus "outside" is away from the tube's centre line, not away from the origin: on the inner
    // side the surface faces the axis.
    const float major = 2.0f;
    const MeshData torus = gsv::make_torus(40, 16, major, 0.5f);
    const int torus_checked = for_each_proper_triangle(torus, [&](glm::vec3 face, glm::vec3 a, glm::vec3 b,
                                                                  glm::vec3 c, std::size_t t) {
        INFO("torus triangle " << t);
        const glm::vec3 centroid = (a + b + c) / 3.0f;
        const glm::vec3 tube_centre = major * glm::normalize(glm::vec3(centroid.x, 0.0f, centroid.z));
        REQUIRE(glm::dot(face, centroid - tube_centre) > 0.0f);
        // The winding must agree with the normals the lighting will use.
        for (int k = 0; k < 3; ++k) REQUIRE(glm::dot(face, torus.normals[torus.indices[3 * t + k]]) > 0.0f);
    });
    CHECK(torus_checked == static_cast<int>(torus.triangle_count()));
}

TEST_CASE("mesh_data: torus normals match the analytic formula", "[unit]") {
    const float major = 1.5f;
    const float minor = 0.4f;
    const MeshData torus = gsv::make_torus(36, 18, major, minor);
    check_well_formed(torus);
    for (std::size_t i = 0; i < torus.positions.size(); ++i) {
        INFO("vertex " << i);
        const glm::vec3 p = torus.positions[i];
        const glm::vec3 tube_centre = major * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
        REQUIRE(std::abs(glm::length(p - tube_centre) - minor) < 1e-5f);
        REQUIRE(glm::length(torus.normals[i] - glm::normalize(p - tube_centre)) < 1e-5f);
    }
}

TEST_CASE("mesh_data: bad shape arguments throw gsv::Error naming the value", "[unit]") {
    CHECK(contains(error_message([] { gsv::make_uv_sphere(2, 8); }), "slices must be at least 3, got 2"));
    CHECK(contains(error_message([] { gsv::make_uv_sphere(8, 1); }), "stacks must be at least 2, got 1"));
    CHECK(contains(error_message([] { gsv::make_uv_sphere(8, 4, 0.0f); }), "radius"));
    CHECK(contains(error_message([] { gsv::make_uv_sphere(8, 4, -1.0f); }), "-1"));
    CHECK(contains(error_message([] { gsv::make_uv_sphere(8, 4, std::nanf("")); }), "radius"));
    CHECK(contains(error_message([] { gsv::make_torus(2, 8, 1.0f, 0.5f); }),
                   "major_segments must be at least 3, got 2"));
    CHECK(contains(error_message([] { gsv::make_torus(8, -1, 1.0f, 0.5f); }),
                   "minor_segments must be at least 3, got -1"));
    CHECK(contains(error_message([] { gsv::make_torus(8, 8, 0.0f, 0.5f); }), "major_radius"));
    CHECK(contains(error_message([] { gsv::make_torus(8, 8, 1.0f, 1.0f); }), "minor_radius"));
    CHECK(contains(error_message([] { gsv::make_torus(8, 8, 1.0f, -0.1f); }), "minor_radius"));
    CHECK(contains(error_message([] { gsv::make_torus(8, 8, INFINITY, 0.5f); }), "major_radius"));
}

TEST_CASE("mesh_data: OBJ with quads, negative indices and every corner form loads", "[unit]") {
    TempDir dir;
    const fs::path file = dir.write("square.obj",
                                    "# a unit square and a triangle over it\r\n"
                                    "mtllib square.mtl\n"
                                    "o square\n"
                                    "v 0 0 0\n"
                                    "v 1 0 0\n"
                                    "v 1 1 0\n"
                                    "v 0 1 0\n"
                                    "vn 0 0 2   # not unit length on purpose\n"
                                    "vt 0 0\n"
                                    "vt 1 0\n"
                                    "vt 1 1\n"
                                    "vt 0 1\n"
                                    "g front\n"
                                    "s 1\n"
                                    "usemtl red\n"
                                    "f 1/1/1 2/2/1 3/3/1 4/4/1\n"     // quad: 4 vertices, 2 triangles
                                    "f -4//-1 -3//-1 -2//-1\n"        // no texcoord: 3 new vertices
                                    "bevel off\n"                     // unknown keyword: ignored
                                    "f 1/1/1 3/3/1 -1/-1/-1\n"        // all reused
                                    "f 2/2 3/3 4/4\n"                 // no normal: 3 new vertices
                                    "l 1 2\n");
    const MeshData mesh = gsv::load_obj(file);
    check_well_formed(mesh);
    CHECK(mesh.positions.size() == 4 + 3 + 3);
    CHECK(mesh.triangle_count() == 2 + 1 + 1 + 1);
    CHECK(mesh.texcoords.size() == mesh.positions.size());
    for (glm::vec3 n : mesh.normals) CHECK(glm::length(n - glm::vec3(0, 0, 1)) < 1e-6f);

    // Fan order: the quad 1 2 3 4 becomes (1 2 3) and (1 3 4).
    const auto position_of = [&](std::size_t corner) { return mesh.positions[mesh.indices[corner]]; };
    CHECK(position_of(3) == glm::vec3(0, 0, 0));
    CHECK(position_of(4) == glm::vec3(1, 1, 0));
    CHECK(position_of(5) == glm::vec3(0, 1, 0));
    // The second face's -4 is the first of the four positions defined by then.
    CHECK(position_of(6) == glm::vec3(0, 0, 0));
    CHECK(mesh.texcoords[mesh.indices[6]] == glm::vec2(0, 0));  // the v//vn corner gets (0, 0)
    CHECK(mesh.texcoords[mesh.indices[1]] == glm::vec2(1, 0));
    // The third face reuses the quad's vertices, since its (v, vt, vn) triples are the same.
    CHECK(mesh.indices[9] == mesh.indices[0]);
    CHECK(mesh.indices[11] == mesh.indices[3 + 2]);
}

TEST_CASE("mesh_data: OBJ negative indices count back from the elements read so far", "[unit]") {
    TempDir dir;
    const fs::path file = dir.write("two.obj",
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                    "f -3 -2 -1\n"
                                    "v 5 0 0\nv 6 0 0\nv 5 1 0\n"
                                    "f -3 -2 -1\n");
    const MeshData mesh = gsv::load_obj(file);
    REQUIRE(mesh.triangle_count() == 2);
    CHECK(mesh.positions[mesh.indices[3]] == glm::vec3(5, 0, 0));
    CHECK(mesh.positions[mesh.indices[5]] == glm::vec3(5, 1, 0));
}

TEST_CASE("mesh_data: OBJ tolerates CRLF, tabs, a byte-order mark and trailing comments", "[unit]") {
    TempDir dir;
    const fs::path file = dir.write("windows.obj",
                                    "\xEF\xBB\xBFv 0 0 0\r\n"
                                    "v\t1.5e0\t0\t0 # x = 1.5\r\n"
                                    "v +0 1 -0.0\r\n"
                                    "\r\n"
                                    "f 1 2 3\r\n");
    const MeshData mesh = gsv::load_obj(file);
    REQUIRE(mesh.positions.size() == 3);
    CHECK(mesh.positions[0] == glm::vec3(0, 0, 0));
    CHECK(mesh.positions[1] == glm::vec3(1.5f, 0, 0));
    CHECK(mesh.positions[2] == glm::vec3(0, 1, 0));
}

TEST_CASE("mesh_data: OBJ without normals gets unit normals", "[unit]") {
    TempDir dir;
    // A pentagon in the xy plane and a tetrahedron, no vn at all and no texture coordinates.
    const fs::path file = dir.write("plain.obj",
                                    "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\n"
                                    "f 1 2 3 4 5\n"
                                    "v 10 0 0\nv 11 0 0\nv 10 1 0\nv 10 0 1\n"
                                    "f 6 8 7\nf 6 7 9\nf 6 9 8\nf 7 8 9\n");
    const MeshData mesh = gsv::load_obj(file);
    check_well_formed(mesh);
    CHECK(mesh.texcoords.empty());
    CHECK(mesh.triangle_count() == 3 + 4);
    for (int i = 0; i < 5; ++i) CHECK(glm::length(mesh.normals[mesh.indices[0] + i] - glm::vec3(0, 0, 1)) < 1e-6f);
    // The tetrahedron's right-angle corner sees three perpendicular faces, each with a 90 degree angle.
    const glm::vec3 corner_normal = mesh.normals[5];
    REQUIRE(mesh.positions[5] == glm::vec3(10, 0, 0));
    CHECK(glm::length(corner_normal - glm::normalize(glm::vec3(-1, -1, -1))) < 1e-6f);
}

TEST_CASE("mesh_data: OBJ errors name the path and line", "[unit]") {
    TempDir dir;
    const auto message_for = [&](const std::string& name, const std::string& text) {
        const fs::path file = dir.write(name, text);
        return error_message([&] { gsv::load_obj(file); });
    };
    const std::string where = (dir.path / "x.obj").string();

    const fs::path missing = dir.path / "missing.obj";
    const std::string missing_message = error_message([&] { gsv::load_obj(missing); });
    CHECK(missing_message == "cannot open OBJ file '" + missing.string() + "'");
    CHECK(contains(error_message([&] { gsv::load_obj(dir.path); }), "cannot open OBJ file"));

    std::string message = message_for("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n");
    CHECK(contains(message, where + ":5:"));
    CHECK(contains(message, "out of range"));
    CHECK(contains(message_for("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), where + ":4: vertex index 0"));
    CHECK(contains(message_for("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n"), where + ":4: vertex index -4"));
    CHECK(contains(message_for("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/2 2/1 3/1\n"),
                   where + ":5: texture coordinate index 2"));
    CHECK(contains(message_for("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n"),
                   where + ":4: normal index 1"));

    message = message_for("x.obj", "v 0 0 0\nv 1 abc 0\n");
    CHECK(contains(message, where + ":2:"));
    CHECK(contains(message, "malformed number 'abc'"));
    CHECK(contains(message_for("x.obj", "v 0 0 0\nvn 1 0 1.5.2\n"), where + ":2: malformed number '1.5.2'"));
    CHECK(contains(message_for("x.obj", "v 0 0 nan\n"), where + ":1: malformed number 'nan'"));
    CHECK(contains(message_for("x.obj", "v 0 0\n"), where + ":1:"));
    CHECK(contains(message_for("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n"), where + ":4:"));
    CHECK(contains(message_for("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n"),
                   where + ":4: malformed face corner"));

    message = message_for("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n# comment\nf 1 2\n");
    CHECK(contains(message, where + ":5:"));
    CHECK(contains(message, "face has 2 vertices"));

    message = message_for("x.obj", "# only vertices\nv 0 0 0\nv 1 0 0\n");
    CHECK(contains(message, where));
    CHECK(contains(message, "no faces"));
}

TEST_CASE("mesh_data: OBJ with a zero-length normal falls back to a computed one", "[unit]") {
    TempDir dir;
    const fs::path file = dir.write("zero_normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nvn 0 0 1\n"
                                                        "f 1//1 2//2 3//2\n");
    const MeshData mesh = gsv::load_obj(file);
    check_well_formed(mesh);
    for (glm::vec3 n : mesh.normals) CHECK(glm::length(n - glm::vec3(0, 0, 1)) < 1e-6f);
}

TEST_CASE("mesh_data: compute_vertex_normals survives zero-area triangles and weights by angle", "[unit]") {
    MeshData mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},   // a proper triangle
                      {2, 0, 0}, {3, 0, 0}, {4, 0, 0},   // collinear: zero area
                      {5, 5, 5}};                        // only in a triangle that repeats it
    mesh.indices = {0, 1, 2, 3, 4, 5, 0, 3, 4, 6, 6, 6, 1, 1, 2};
    gsv::compute_vertex_normals(mesh);
    check_well_formed(mesh);
    CHECK(glm::length(mesh.normals[0] - glm::vec3(0, 0, 1)) < 1e-6f);
    CHECK(glm::length(mesh.normals[1] - glm::vec3(0, 0, 1)) < 1e-6f);
    // Vertices in no usable triangle get the documented fallback.
    CHECK(mesh.normals[5] == glm::vec3(0, 0, 1));
    CHECK(mesh.normals[6] == glm::vec3(0, 0, 1));

    // A NaN position must not leak into the normals.
    MeshData broken;
    broken.positions = {{0, 0, 0}, {1, 0, 0}, {std::nanf(""), 1, 0}};
    broken.indices = {0, 1, 2};
    gsv::compute_vertex_normals(broken);
    for (glm::vec3 n : broken.normals) CHECK(finite(n));

    // Cube corner with one face split into two triangles at the corner: the angle weighting keeps the
    // split face from counting double, so the normal stays on the diagonal.
    MeshData corner;
    corner.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    corner.indices = {0, 2, 4, 0, 4, 1,   // the z = 0 face, split through the corner
                      0, 3, 2,            // x = 0
                      0, 1, 3};           // y = 0
    gsv::compute_vertex_normals(corner);
    CHECK(glm::length(corner.normals[0] - glm::normalize(glm::vec3(-1, -1, -1))) < 1e-6f);
}

TEST_CASE("mesh_data: normal_matrix keeps normals perpendicular under non-uniform scale", "[unit]") {
    const glm::mat4 model_view = glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, 1.0f, 1.0f));
    // A surface at 45 degrees: normal (1, 1, 0), spanned by the tangents (1, -1, 0) and (0, 0, 1).
    const glm::vec3 normal = glm::normalize(glm::vec3(1, 1, 0));
    const glm::dvec3 tangents[] = {{1, -1, 0}, {0, 0, 1}};

    const glm::vec3 transformed = glm::normalize(gsv::normal_matrix(model_view) * normal);
    const glm::dmat3 linear{glm::dmat4(model_view)};
    const glm::dvec3 expected = glm::normalize(glm::transpose(glm::inverse(linear)) * glm::dvec3(normal));
    CHECK(glm::length(glm::dvec3(transformed) - expected) < 1e-6);
    for (const glm::dvec3& tangent : tangents)
        CHECK(std::abs(glm::dot(glm::dvec3(transformed), glm::normalize(linear * tangent))) < 1e-6);
    // The plain 3x3 tilts the normal off the surface, which is why the inverse-transpose is needed.
    const glm::dvec3 naive = glm::normalize(linear * glm::dvec3(normal));
    CHECK(std::abs(glm::dot(naive, glm::normalize(linear * tangents[0]))) > 0.1);
    CHECK(glm::length(glm::dvec3(transformed) - glm::normalize(glm::dvec3(1, 2, 0))) < 1e-6);
}

TEST_CASE("mesh_data: normal_matrix equals the model-view's 3x3 for a rotation, and rejects singular ones", "[unit]") {
    const glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    const glm::mat4 model_view = glm::translate(glm::mat4(1.0f), glm::vec3(4, -5, 6)) * rotation;
    const glm::mat3 result = gsv::normal_matrix(model_view);
    const glm::mat3 linear(model_view);
    for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row) CHECK(std::abs(result[column][row] - linear[column][row]) < 1e-6f);

    const glm::mat4 flattened = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 1.0f));
    CHECK(contains(error_message([&] { gsv::normal_matrix(flattened); }), "singular"));
}

TEST_CASE("mesh_data: bounds and normalize_to_unit_sphere", "[unit]") {
    MeshData torus = gsv::make_torus(24, 12, 30.0f, 10.0f);
    for (glm::vec3& p : torus.positions) p += glm::vec3(100.0f, -7.0f, 3.0f);
    const gsv::Bounds before = gsv::bounds_of(torus);
    CHECK(glm::length(before.center() - glm::vec3(100.0f, -7.0f, 3.0f)) < 1e-3f);
    CHECK(std::abs(before.max.y - before.min.y - 20.0f) < 1e-3f);

    const std::vector<glm::vec3> normals_before = torus.normals;
    gsv::normalize_to_unit_sphere(torus);
    const gsv::Bounds after = gsv::bounds_of(torus);
    CHECK(glm::length(after.center()) < 1e-5f);
    CHECK(std::abs(after.radius() - 1.0f) < 1e-5f);
    for (glm::vec3 p : torus.positions) CHECK(glm::length(p) <= 1.0f + 1e-5f);
    CHECK(torus.normals == normals_before);

    CHECK(contains(error_message([] { gsv::bounds_of(MeshData{}); }), "no positions"));
    MeshData point;
    point.positions = {{1, 2, 3}, {1, 2, 3}};
    point.normals = {{0, 0, 1}, {0, 0, 1}};
    CHECK(contains(error_message([&] { gsv::normalize_to_unit_sphere(point); }), "radius"));
}

TEST_CASE("mesh_data: the shipped data/meshes/teapot.obj loads", "[unit]") {
    const fs::path file = source_root() / "data" / "meshes" / "teapot.obj";
    INFO(file.string());
    MeshData teapot = gsv::load_obj(file);
    check_well_formed(teapot);
    CHECK(teapot.triangle_count() > 10000);
    CHECK(teapot.texcoords.size() == teapot.positions.size());
    const gsv::Bounds bounds = gsv::bounds_of(teapot);
    CHECK(std::abs(bounds.min.y) < 1e-5f);     // base on the ground plane
    CHECK(bounds.max.x > -bounds.min.x * 0.5f);  // spout toward +x, handle toward -x
    // The shading normals must agree with the winding, or lighting would come out inside out.
    int disagreeing = 0;
    const int checked = for_each_proper_triangle(teapot, [&](glm::vec3 face, glm::vec3, glm::vec3, glm::vec3,
                                                             std::size_t t) {
        glm::vec3 normal_sum(0.0f);
        for (int k = 0; k < 3; ++k) normal_sum += teapot.normals[teapot.indices[3 * t + k]];
        if (glm::dot(face, normal_sum) <= 0.0f) ++disagreeing;
    });
    CHECK(checked > 10000);
    CHECK(disagreeing == 0);
    gsv::normalize_to_unit_sphere(teapot);
    CHECK(std::abs(gsv::bounds_of(teapot).radius() - 1.0f) < 1e-5f);
}
