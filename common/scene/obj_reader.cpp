// load_obj (mesh_data.h): the triangle part of a Wavefront OBJ file, each malformed line named by file and line.
#include "common/scene/mesh_data.h"

#include "common/core/error.h"

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

}  // namespace gsv
