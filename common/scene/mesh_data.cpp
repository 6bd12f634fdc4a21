#include "common/scene/mesh_data.h"

#include "common/core/error.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>

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
// OBJ

namespace {

std::vector<std::string_view> split_whitespace(std::string_view text) {
    std::vector<std::string_view> tokens;
    std::size_t pos = 0;
    while (true) {
        pos = text.find_first_not_of(" \t\r\f\v", pos);
        if (pos == std::string_view::npos) break;
        const std::size_t end = std::min(text.find_first_of(" \t\r\f\v", pos), text.size());
        tokens.push_back(text.substr(pos, end - pos));
        pos = end;
    }
    return tokens;
}

class ObjReader {
public:
    explicit ObjReader(const std::filesystem::path& path) : path_(path) {}

    MeshData read() {
        std::error_code ignored;
        std::ifstream in;
        // A directory opens as a stream on Linux and would then read as an empty file.
        if (!std::filesystem::is_directory(path_, ignored)) in.open(path_, std::ios::binary);
        if (!in.is_open()) throw Error("cannot open OBJ file '" + path_.string() + "'");
        std::string line;
        while (std::getline(in, line)) {
            ++line_number_;
            // Some Windows editors start UTF-8 files with a byte-order mark, which would hide the first keyword.
            if (line_number_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
            parse_line(line);
        }
        if (in.bad()) throw Error("cannot read OBJ file '" + path_.string() + "'");
        if (mesh_.indices.empty()) throw Error(path_.string() + ": no faces, so there is no mesh to draw");
        return finish();
    }

private:
    struct Corner {
        int position;
        int texcoord;  // -1: none
        int normal;    // -1: none
        bool operator==(const Corner& other) const {
            return position == other.position && texcoord == other.texcoord && normal == other.normal;
        }
    };
    struct CornerHash {
        std::size_t operator()(const Corner& c) const {
            std::size_t h = std::hash<int>()(c.position);
            h = h * 1000003u ^ std::hash<int>()(c.texcoord);
            return h * 1000003u ^ std::hash<int>()(c.normal);
        }
    };

    [[noreturn]] void fail(const std::string& what) const {
        throw Error(path_.string() + ":" + std::to_string(line_number_) + ": " + what);
    }

    float parse_float(std::string_view token) const {
        std::string_view digits = token;
        // from_chars is locale-independent but, unlike strtod, rejects a leading '+'; strip one, but
        // only before a digit or point so that "+-1" stays malformed.
        if (digits.size() > 1 && digits[0] == '+' &&
            (std::isdigit(static_cast<unsigned char>(digits[1])) || digits[1] == '.'))
            digits.remove_prefix(1);
        float value = 0.0f;
#ifdef __EMSCRIPTEN__
        // Emscripten 3.1's libc++ has no floating-point from_chars. Its C library runs in the C locale, so strtof
        // reads what from_chars would, once the hexadecimal form from_chars refuses is refused here too.
        const std::string text(digits);
        char* stop = nullptr;
        value = text.find_first_of("xX") == std::string::npos ? std::strtof(text.c_str(), &stop) : 0.0f;
        const bool whole = stop == text.c_str() + text.size() && !text.empty() && !std::isspace(static_cast<unsigned char>(text[0]));
#else
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        const bool whole = error == std::errc() && end == digits.data() + digits.size();
#endif
        // Non-finite values (from_chars takes "inf" and "nan") would poison bounds and normals later.
        if (!whole || !std::isfinite(value)) fail("malformed number '" + std::string(token) + "'");
        return value;
    }

    glm::vec3 parse_vec3(const std::vector<std::string_view>& tokens, std::size_t min_count,
                         std::size_t max_count) const {
        const std::size_t count = tokens.size() - 1;
        if (count < min_count || count > max_count)
            fail("'" + std::string(tokens[0]) + "' needs " + std::to_string(min_count) +
                 (min_count == max_count ? "" : " to " + std::to_string(max_count)) + " numbers, got " +
                 std::to_string(count));
        glm::vec3 value(0.0f);
        for (std::size_t i = 0; i < count; ++i) {
            const float number = parse_float(tokens[i + 1]);
            if (i < 3) value[static_cast<glm::length_t>(i)] = number;
        }
        return value;
    }

    // Turns a 1-based or negative (relative) OBJ index into a 0-based index among the `defined` items
    // read so far.
    int resolve_index(std::string_view text, std::size_t defined, const char* kind) const {
        int index = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
        if (error != std::errc() || end != text.data() + text.size() || text.empty())
            fail("malformed " + std::string(kind) + " index '" + std::string(text) + "'");
        const auto count = static_cast<long long>(defined);
        const long long resolved = index < 0 ? count + index : static_cast<long long>(index) - 1;
        if (index == 0 || resolved < 0 || resolved >= count)
            fail(std::string(kind) + " index " + std::string(text) + " out of range (" + std::to_string(count) +
                 " defined so far)");
        return static_cast<int>(resolved);
    }

    Corner parse_corner(std::string_view token) const {
        std::string_view parts[3];
        std::size_t part_count = 0;
        std::size_t start = 0;
        while (true) {
            const std::size_t slash = token.find('/', start);
            if (part_count == 3) fail("malformed face corner '" + std::string(token) + "'");
            parts[part_count++] = token.substr(start, slash == std::string_view::npos ? slash : slash - start);
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        Corner corner{resolve_index(parts[0], positions_.size(), "vertex"), -1, -1};
        if (part_count >= 2 && !parts[1].empty())
            corner.texcoord = resolve_index(parts[1], texcoords_.size(), "texture coordinate");
        if (part_count == 3) {
            if (parts[2].empty()) fail("malformed face corner '" + std::string(token) + "'");
            corner.normal = resolve_index(parts[2], normals_.size(), "normal");
        }
        return corner;
    }

    std::uint32_t vertex_for(const Corner& corner) {
        const auto found = vertex_of_corner_.find(corner);
        if (found != vertex_of_corner_.end()) return found->second;
        const auto vertex = static_cast<std::uint32_t>(corners_.size());
        corners_.push_back(corner);
        vertex_of_corner_.emplace(corner, vertex);
        return vertex;
    }

    void parse_line(std::string_view line) {
        line = line.substr(0, line.find('#'));
        const std::vector<std::string_view> tokens = split_whitespace(line);
        if (tokens.empty()) return;
        const std::string_view keyword = tokens[0];
        if (keyword == "v") {
            // x y z, optionally w or an r g b colour extension, which are checked but not kept.
            positions_.push_back(parse_vec3(tokens, 3, 7));
        } else if (keyword == "vn") {
            normals_.push_back(parse_vec3(tokens, 3, 3));
        } else if (keyword == "vt") {
            const glm::vec3 uvw = parse_vec3(tokens, 1, 3);
            texcoords_.emplace_back(uvw.x, uvw.y);
        } else if (keyword == "f") {
            const std::size_t corner_count = tokens.size() - 1;
            if (corner_count < 3)
                fail("face has " + std::to_string(corner_count) + " vertices, needs at least 3");
            std::vector<std::uint32_t> polygon;
            polygon.reserve(corner_count);
            for (std::size_t i = 1; i < tokens.size(); ++i) polygon.push_back(vertex_for(parse_corner(tokens[i])));
            for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
                mesh_.indices.insert(mesh_.indices.end(), {polygon[0], polygon[i], polygon[i + 1]});
        }
        // Anything else (o, g, s, usemtl, mtllib, l, p, or keywords of other OBJ dialects) does not affect
        // the triangles, and skipping it keeps files from other exporters loadable.
    }

    MeshData finish() {
        const bool any_texcoords =
            std::any_of(corners_.begin(), corners_.end(), [](const Corner& c) { return c.texcoord >= 0; });
        std::vector<bool> needs_normal(corners_.size(), false);
        for (std::size_t i = 0; i < corners_.size(); ++i) {
            const Corner& corner = corners_[i];
            mesh_.positions.push_back(positions_[static_cast<std::size_t>(corner.position)]);
            if (any_texcoords)
                mesh_.texcoords.push_back(corner.texcoord >= 0 ? texcoords_[static_cast<std::size_t>(corner.texcoord)]
                                                               : glm::vec2(0.0f));
            glm::vec3 normal(0.0f);
            if (corner.normal >= 0) {
                const glm::vec3 given = normals_[static_cast<std::size_t>(corner.normal)];
                const float length = glm::length(given);
                // Exporters write normals rounded to a few digits, and some write zero vectors.
                if (std::isfinite(length) && length > 1e-12f) normal = given / length;
                else needs_normal[i] = true;
            } else {
                needs_normal[i] = true;
            }
            mesh_.normals.push_back(normal);
        }
        if (std::find(needs_normal.begin(), needs_normal.end(), true) != needs_normal.end()) {
            MeshData computed = mesh_;
            compute_vertex_normals(computed);
            for (std::size_t i = 0; i < corners_.size(); ++i)
                if (needs_normal[i]) mesh_.normals[i] = computed.normals[i];
        }
        return std::move(mesh_);
    }

    std::filesystem::path path_;
    int line_number_ = 0;
    std::vector<glm::vec3> positions_;
    std::vector<glm::vec3> normals_;
    std::vector<glm::vec2> texcoords_;
    std::vector<Corner> corners_;  // one per output vertex
    std::unordered_map<Corner, std::uint32_t, CornerHash> vertex_of_corner_;
    MeshData mesh_;
};

}  // namespace

MeshData load_obj(const std::filesystem::path& path) { return ObjReader(path).read(); }

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
