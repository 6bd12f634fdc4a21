#pragma once
// CPU-side triangle meshes: procedural shapes with exact normals, a Wavefront OBJ reader, and the
// normal bookkeeping (vertex normals, normal matrix, bounds) that every lighting lab needs. No GL here,
// so all of it is testable without a context.
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace gsv {

// Coordinates are right-handed with +y up; front faces wind counter-clockwise seen from outside,
// matching GL's default glFrontFace(GL_CCW).
struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;        // unit length, one per position
    std::vector<glm::vec2> texcoords;      // one per position, or empty when the mesh has none
    std::vector<std::uint32_t> indices;    // three per triangle

    std::size_t triangle_count() const { return indices.size() / 3; }
};

// A flat n x n grid of vertices over the unit square in the xz plane: position (u, 0, v), texture
// coordinate (u, v), normal +y; 2 (n-1)^2 triangles. n = 2 is one quad. A vertex shader displaces it
// (lab 04's real terrain geometry). Throws gsv::Error unless 2 <= n <= 4096.
MeshData make_grid(int n);

// A latitude-longitude sphere centred at the origin. u runs with longitude (0 at +z, growing toward +x),
// v with latitude (0 at the south pole, 1 at the north pole, so v grows upward like GL's texture origin).
// The seam column is duplicated so u can reach 1, and each pole is a row of `slices` vertices, one per
// cap triangle, whose u sits mid-slice: a single shared pole vertex could carry only one u.
// Vertices: 2*slices + (stacks-1)*(slices+1); triangles: 2*slices*(stacks-1).
// Throws gsv::Error for slices < 3, stacks < 2, or a radius that is not a positive finite number.
MeshData make_uv_sphere(int slices, int stacks, float radius = 1.0f);
// Its triangles, 2*slices*(stacks-1), without building it (a lab's work per frame, Lab::frame_work).
std::size_t uv_sphere_triangle_count(int slices, int stacks);

// A ring torus around the y axis: a tube of minor_radius swept along a circle of major_radius in the
// xz plane. u runs around the ring (0 at +z, growing toward +x), v around the tube (0 on the outer
// equator, growing upward). Seams are duplicated, so vertices: (major+1)*(minor+1); triangles:
// 2*major*minor. Throws gsv::Error for fewer than 3 segments either way or unless
// 0 < minor_radius < major_radius (a larger tube self-intersects and has no well-defined outside).
MeshData make_torus(int major_segments, int minor_segments, float major_radius, float minor_radius);
// Its triangles, 2*major*minor, without building it.
std::size_t torus_triangle_count(int major_segments, int minor_segments);

// Reads the triangle part of a Wavefront OBJ file: v, vt, vn and f with corners written v, v/vt, v//vn or
// v/vt/vn, 1-based or negative (relative to the elements defined so far) indices, polygons split into
// fans. Other statements (o, g, s, usemtl, mtllib, l, p, unknown keywords) and '#' comments are skipped.
// Each distinct (v, vt, vn) corner becomes one vertex. Corners without a usable normal get the normal
// compute_vertex_normals gives them; when some corners have texture coordinates and others do not, the
// others get (0, 0). Throws gsv::Error "cannot open OBJ file 'path'" when the file cannot be read, and
// "path:line: what" for a malformed number, an index out of range, or a face with fewer than three
// corners; a file without faces is an error too.
MeshData load_obj(const std::filesystem::path& path);  // obj_reader.cpp

// Replaces mesh.normals with the angle-weighted average of the adjacent triangles' normals: angle
// weighting keeps the result independent of how a flat region happens to be split into triangles.
// Triangles thinner than a millionth of their longest edge are skipped, their normal being rounding
// noise. A vertex with no usable triangle gets (0, 0, 1), which faces the default camera: the fault then
// shows up as a lit patch rather than as NaNs that blacken or discard whole pixels.
void compute_vertex_normals(MeshData& mesh);

// The matrix that carries normals into eye space: the inverse-transpose of the upper-left 3x3. The 3x3
// itself would tilt normals off their surface under non-uniform scale; for rotations the two coincide.
// Throws gsv::Error when the 3x3 is singular, since no normal transform exists then.
glm::mat3 normal_matrix(const glm::mat4& model_view);

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};

    glm::vec3 center() const { return 0.5f * (min + max); }
    // Radius of the sphere around center() through the box's corners, so it encloses every vertex.
    float radius() const { return 0.5f * glm::length(max - min); }
};

// The axis-aligned box around the positions; throws gsv::Error for a mesh without positions.
Bounds bounds_of(const MeshData& mesh);

// Moves the bounds' centre to the origin and scales uniformly so Bounds::radius() becomes 1, letting a
// lab frame any loaded model with one fixed camera. Uniform scaling leaves the normals valid.
// Throws gsv::Error for a mesh without positions or with all positions at one point.
void normalize_to_unit_sphere(MeshData& mesh);

}  // namespace gsv
