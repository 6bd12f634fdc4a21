#include "common/scene/mesh_data.h"

#include "common/core/error.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace gsv {
namespace {

constexpr float kTwoPi = glm::two_pi<float>();

bool positive_finite(float value) { return std::isfinite(value) && value > 0.0f; }

// Adds the two triangles of the grid cell whose lower-left corner is `a`, counter-clockwise when u grows
// to the right and v upward as seen from outside.
void add_cell(std::vector<std::uint32_t>& indices, std::uint32_t a, std::uint32_t b, std::uint32_t c,
              std::uint32_t d) {
    // a = (u, v), b = (u+1, v), c = (u+1, v+1), d = (u, v+1)
    indices.insert(indices.end(), {a, b, c, a, c, d});
}

}  // namespace

MeshData make_grid(int n) {
    if (n < 2 || n > 4096) throw Error("make_grid: " + std::to_string(n) + " vertices per side is not in 2..4096");
    MeshData grid;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec2 uv(static_cast<float>(i) / static_cast<float>(n - 1), static_cast<float>(j) / static_cast<float>(n - 1));
            grid.positions.emplace_back(uv.x, 0.0f, uv.y);
            grid.normals.emplace_back(0.0f, 1.0f, 0.0f);
            grid.texcoords.push_back(uv);
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const auto at = [n](int x, int y) { return static_cast<std::uint32_t>(y * n + x); };
            // Counter-clockwise seen from +y.
            grid.indices.insert(grid.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return grid;
}

MeshData make_uv_sphere(int slices, int stacks, float radius) {
    if (slices < 3) throw Error("make_uv_sphere: slices must be at least 3, got " + std::to_string(slices));
    if (stacks < 2) throw Error("make_uv_sphere: stacks must be at least 2, got " + std::to_string(stacks));
    if (!positive_finite(radius))
        throw Error("make_uv_sphere: radius must be positive and finite, got " + std::to_string(radius));

    MeshData mesh;
    const auto add_vertex = [&](glm::vec3 direction, glm::vec2 uv) {
        mesh.positions.push_back(radius * direction);
        mesh.normals.push_back(direction);
        mesh.texcoords.push_back(uv);
    };
    // Trig of the longitude is taken modulo `slices` so the duplicated seam column is bit-identical to
    // the first one; otherwise rounding in sin(2*pi) would open a hairline crack along the seam.
    const auto ring_direction = [&](int slice, float polar) {
        const float longitude = kTwoPi * static_cast<float>(slice % slices) / static_cast<float>(slices);
        return glm::vec3(std::sin(polar) * std::sin(longitude), std::cos(polar),
                         std::sin(polar) * std::cos(longitude));
    };

    // The poles get exact axis normals rather than trig results, which are off by rounding at pi.
    const auto south_pole = static_cast<std::uint32_t>(mesh.positions.size());
    for (int slice = 0; slice < slices; ++slice)
        add_vertex({0.0f, -1.0f, 0.0f}, {(static_cast<float>(slice) + 0.5f) / static_cast<float>(slices), 0.0f});

    const auto first_ring = static_cast<std::uint32_t>(mesh.positions.size());
    const auto ring_size = static_cast<std::uint32_t>(slices + 1);
    for (int stack = 1; stack < stacks; ++stack) {
        const float v = static_cast<float>(stack) / static_cast<float>(stacks);
        const float polar = glm::pi<float>() * (1.0f - v);  // angle from +y
        for (int slice = 0; slice <= slices; ++slice)
            add_vertex(ring_direction(slice, polar), {static_cast<float>(slice) / static_cast<float>(slices), v});
    }

    const auto north_pole = static_cast<std::uint32_t>(mesh.positions.size());
    for (int slice = 0; slice < slices; ++slice)
        add_vertex({0.0f, 1.0f, 0.0f}, {(static_cast<float>(slice) + 0.5f) / static_cast<float>(slices), 1.0f});

    const auto rings = static_cast<std::uint32_t>(stacks - 1);
    const auto last_ring = first_ring + (rings - 1) * ring_size;
    for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(slices); ++s) {
        // Cap triangles: the quads touching a pole collapse to one triangle each.
        mesh.indices.insert(mesh.indices.end(), {south_pole + s, first_ring + s + 1, first_ring + s});
        mesh.indices.insert(mesh.indices.end(), {north_pole + s, last_ring + s, last_ring + s + 1});
        for (std::uint32_t ring = 0; ring + 1 < rings; ++ring) {
            const std::uint32_t a = first_ring + ring * ring_size + s;
            add_cell(mesh.indices, a, a + 1, a + 1 + ring_size, a + ring_size);
        }
    }
    return mesh;
}

std::size_t uv_sphere_triangle_count(int slices, int stacks) {
    // A cap triangle a slice at each pole, and two a cell of the stacks - 2 bands between the rings.
    return 2 * static_cast<std::size_t>(slices) * static_cast<std::size_t>(stacks - 1);
}

std::size_t torus_triangle_count(int major_segments, int minor_segments) {
    return 2 * static_cast<std::size_t>(major_segments) * static_cast<std::size_t>(minor_segments);
}

MeshData make_torus(int major_segments, int minor_segments, float major_radius, float minor_radius) {
    if (major_segments < 3)
        throw Error("make_torus: major_segments must be at least 3, got " + std::to_string(major_segments));
    if (minor_segments < 3)
        throw Error("make_torus: minor_segments must be at least 3, got " + std::to_string(minor_segments));
    if (!positive_finite(major_radius))
        throw Error("make_torus: major_radius must be positive and finite, got " + std::to_string(major_radius));
    if (!positive_finite(minor_radius) || !(minor_radius < major_radius))
        throw Error("make_torus: minor_radius must be positive and below major_radius " +
                    std::to_string(major_radius) + ", got " + std::to_string(minor_radius));

    MeshData mesh;
    const auto row_size = static_cast<std::uint32_t>(minor_segments + 1);
    for (int i = 0; i <= major_segments; ++i) {
        const float u = static_cast<float>(i) / static_cast<float>(major_segments);
        // Modulo so the seam's duplicated vertices are bit-identical to the first ones.
        const float around = kTwoPi * static_cast<float>(i % major_segments) / static_cast<float>(major_segments);
        const glm::vec3 outward(std::sin(around), 0.0f, std::cos(around));
        for (int j = 0; j <= minor_segments; ++j) {
            const float v = static_cast<float>(j) / static_cast<float>(minor_segments);
            const float tube = kTwoPi * static_cast<float>(j % minor_segments) / static_cast<float>(minor_segments);
            const glm::vec3 normal = std::cos(tube) * outward + glm::vec3(0.0f, std::sin(tube), 0.0f);
            mesh.positions.push_back(major_radius * outward + minor_radius * normal);
            mesh.normals.push_back(glm::normalize(normal));
            mesh.texcoords.emplace_back(u, v);
        }
    }
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(major_segments); ++i)
        for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(minor_segments); ++j) {
            const std::uint32_t a = i * row_size + j;
            add_cell(mesh.indices, a, a + row_size, a + row_size + 1, a + 1);
        }
    return mesh;
}

// ---------------------------------------------------------------------------------------------------
// Normals and bounds

void compute_vertex_normals(MeshData& mesh) {
    // Double accumulators: a vertex of a fine mesh sums many nearly cancelling contributions.
    std::vector<glm::dvec3> sums(mesh.positions.size(), glm::dvec3(0.0));
    const std::size_t vertex_count = mesh.positions.size();
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t corner[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        if (corner[0] >= vertex_count || corner[1] >= vertex_count || corner[2] >= vertex_count)
            throw Error("compute_vertex_normals: triangle " + std::to_string(t / 3) + " indexes past the " +
                        std::to_string(vertex_count) + " vertices");
        const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[corner[0]]), glm::dvec3(mesh.positions[corner[1]]),
                                 glm::dvec3(mesh.positions[corner[2]])};
        const glm::dvec3 edge[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};  // edge[k] leaves corner k
        const glm::dvec3 area_normal = glm::cross(edge[0], -edge[2]);
        const double twice_area = glm::length(area_normal);
        const double longest_squared =
            std::max({glm::dot(edge[0], edge[0]), glm::dot(edge[1], edge[1]), glm::dot(edge[2], edge[2])});
        // Negated comparison so NaN positions are skipped as well.
        if (!(twice_area > 1e-6 * longest_squared)) continue;
        const glm::dvec3 face_normal = area_normal / twice_area;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 outgoing = edge[k];
            const glm::dvec3 incoming_reversed = -edge[(k + 2) % 3];
            // atan2 of |cross| and dot stays accurate for angles near 0 and pi, where acos does not.
            const double angle = std::atan2(glm::length(glm::cross(outgoing, incoming_reversed)),
                                            glm::dot(outgoing, incoming_reversed));
            sums[corner[k]] += angle * face_normal;
        }
    }
    mesh.normals.resize(vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i) {
        const double length = glm::length(sums[i]);
        mesh.normals[i] = length > 1e-12 && std::isfinite(length) ? glm::vec3(sums[i] / length)
                                                                  : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

glm::mat3 normal_matrix(const glm::mat4& model_view) {
    const glm::mat3 linear(model_view);
    const float determinant = glm::determinant(linear);
    if (!std::isfinite(determinant) || determinant == 0.0f)
        throw Error("normal_matrix: the model-view's 3x3 part is singular (determinant " +
                    std::to_string(determinant) + ")");
    return glm::transpose(glm::inverse(linear));
}

Bounds bounds_of(const MeshData& mesh) {
    if (mesh.positions.empty()) throw Error("bounds_of: the mesh has no positions");
    Bounds bounds{mesh.positions.front(), mesh.positions.front()};
    for (const glm::vec3& p : mesh.positions) {
        bounds.min = glm::min(bounds.min, p);
        bounds.max = glm::max(bounds.max, p);
    }
    return bounds;
}

void normalize_to_unit_sphere(MeshData& mesh) {
    const Bounds bounds = bounds_of(mesh);
    const float radius = bounds.radius();
    if (!(radius > 0.0f) || !std::isfinite(radius))
        throw Error("normalize_to_unit_sphere: the mesh's bounding radius is " + std::to_string(radius));
    const glm::vec3 center = bounds.center();
    for (glm::vec3& p : mesh.positions) p = (p - center) / radius;
}

}  // namespace gsv
