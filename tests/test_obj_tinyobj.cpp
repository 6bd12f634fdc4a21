// The kit's OBJ reader (common/scene/mesh_data.h) beside a well-kept one, Debian's tinyobjloader, on the real
// teapot and on the same data written as other exporters write OBJ: both must give the same surface. The kit keeps
// its own reader for what tinyobjloader does not do: a malformed number or an index out of range is an error naming
// the file and line (tinyobjloader reads "1.5x" as 1.5 and only warns about an index past the end), and the reader
// runs where no tinyobjloader is installed (a student's laptop).
#include "catch.hpp"
#include "common/scene/mesh_data.h"
#include "test_support.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using gsv::test::TempDir;

namespace {

struct Surface {
    std::size_t triangles = 0;
    double area = 0;
    glm::dvec3 moment{0.0};  // the area-weighted sum of triangle centroids: the same for any triangulation
};

Surface surface_of(const std::vector<glm::dvec3>& corners) {
    Surface s;
    for (std::size_t i = 0; i + 2 < corners.size(); i += 3) {
        const double area = 0.5 * glm::length(glm::cross(corners[i + 1] - corners[i], corners[i + 2] - corners[i]));
        s.area += area;
        s.moment += area * (corners[i] + corners[i + 1] + corners[i + 2]) / 3.0;
        ++s.triangles;
    }
    return s;
}

Surface kit_surface(const fs::path& path) {
    const gsv::MeshData mesh = gsv::load_obj(path);
    std::vector<glm::dvec3> corners;
    for (const auto index : mesh.indices) corners.push_back(glm::dvec3(mesh.positions.at(index)));
    return surface_of(corners);
}

Surface tinyobj_surface(const fs::path& path) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, path.string().c_str(),
                                     path.parent_path().string().c_str(), true);
    INFO(err);
    REQUIRE(ok);
    std::vector<glm::dvec3> corners;
    for (const auto& shape : shapes)
        for (const auto& index : shape.mesh.indices) {
            const auto at = static_cast<std::size_t>(index.vertex_index) * 3;
            REQUIRE(at + 2 < attrib.vertices.size());
            corners.emplace_back(attrib.vertices[at], attrib.vertices[at + 1], attrib.vertices[at + 2]);
        }
    return surface_of(corners);
}

void check_same_surface(const fs::path& path) {
    INFO(path.filename().string());
    const Surface kit = kit_surface(path), reference = tinyobj_surface(path);
    CHECK(kit.triangles == reference.triangles);
    CHECK(kit.area == Approx(reference.area).epsilon(1e-9));
    for (int k = 0; k < 3; ++k) CHECK(kit.moment[k] == Approx(reference.moment[k]).epsilon(1e-9).margin(1e-9));
}

struct ObjData {
    std::vector<std::string> v, vt, vn;
    std::vector<std::vector<std::string>> faces;  // corners as written: "1/1/1"
};

ObjData read_teapot() {
    std::ifstream in(fs::path(GSV_SOURCE_ROOT) / "data/meshes/teapot.obj");
    ObjData data;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string key, rest;
        words >> key;
        std::getline(words, rest);
        if (key == "v") data.v.push_back(rest);
        else if (key == "vt") data.vt.push_back(rest);
        else if (key == "vn") data.vn.push_back(rest);
        else if (key == "f") {
            std::istringstream corners(rest);
            data.faces.emplace_back();
            for (std::string c; corners >> c;) data.faces.back().push_back(c);
        }
    }
    return data;
}

int position_index(const std::string& corner) { return std::stoi(corner.substr(0, corner.find('/'))); }

}  // namespace

TEST_CASE("obj: the kit's reader and tinyobjloader give the same surface on the teapot as exporters write it", "[unit][mesh]") {
    TempDir dir;
    const fs::path teapot = fs::path(GSV_SOURCE_ROOT) / "data/meshes/teapot.obj";
    check_same_surface(teapot);
    const ObjData data = read_teapot();
    REQUIRE(data.faces.size() > 1000);

    // Windows line ends, a byte-order mark, tabs, comments, object, group, smoothing and material lines.
    {
        std::string text = "\xEF\xBB\xBF# exported\r\nmtllib teapot.mtl\r\no teapot\r\ng body\r\ns 1\r\nusemtl china\r\n";
        for (const auto& v : data.v) text += "v\t" + v + "  # a position\r\n";
        for (const auto& t : data.vt) text += "vt " + t + "\r\n";
        for (const auto& n : data.vn) text += "vn " + n + "\r\n";
        for (const auto& f : data.faces) text += "f " + f[0] + "\t" + f[1] + " " + f[2] + "\r\n";
        check_same_surface(dir.write("dialect.obj", text));
    }
    // Positions only, no normals or texture coordinates ("f 1 2 3"), and "f 1//1 2//2 3//3".
    {
        std::string plain, normals;
        for (const auto& v : data.v) plain += "v " + v + "\n";
        normals = plain;
        for (const auto& n : data.vn) normals += "vn " + n + "\n";
        for (const auto& f : data.faces) {
            plain += "f";
            normals += "f";
            for (const auto& c : f) {
                plain += " " + std::to_string(position_index(c));
                normals += " " + std::to_string(position_index(c)) + "//" + std::to_string(position_index(c));
            }
            plain += "\n";
            normals += "\n";
        }
        check_same_surface(dir.write("positions.obj", plain));
        check_same_surface(dir.write("normals.obj", normals));
    }
    // Relative (negative) indices: each face written after its own three vertices.
    {
        std::string text;
        for (const auto& f : data.faces) {
            for (const auto& c : f) text += "v " + data.v.at(static_cast<std::size_t>(position_index(c) - 1)) + "\n";
            text += "f -3 -2 -1\n";
        }
        check_same_surface(dir.write("relative.obj", text));
    }
    // Vertex colours after the position ("v x y z r g b"), as some scanners write.
    {
        std::string text;
        for (const auto& v : data.v) text += "v " + v + " 0.8 0.7 0.6\n";
        for (const auto& f : data.faces)
            text += "f " + std::to_string(position_index(f[0])) + " " + std::to_string(position_index(f[1])) + " " +
                    std::to_string(position_index(f[2])) + "\n";
        check_same_surface(dir.write("colours.obj", text));
    }
}

TEST_CASE("obj: quads and convex polygons become the same surface in both readers", "[unit][mesh]") {
    TempDir dir;
    // A unit cube of quads and a regular hexagon: any triangulation of a convex face has its area and moment.
    std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                       "f 1/1 4/4 3/3 2/2\nf 5/1 6/2 7/3 8/4\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    for (int k = 0; k < 6; ++k)
        text += "v " + std::to_string(3 + std::cos(k * M_PI / 3)) + " " + std::to_string(std::sin(k * M_PI / 3)) + " 0\n";
    text += "f 9 10 11 12 13 14\n";
    check_same_surface(dir.write("polygons.obj", text));
    CHECK(kit_surface(dir.path("polygons.obj")).triangles == 12 + 4);
}
