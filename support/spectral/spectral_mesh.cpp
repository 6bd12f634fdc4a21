#include "support/spectral/spectral_mesh.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"

#include <cmath>

namespace gsv {
namespace {

const double kPi = 3.14159265358979323846;

}  // namespace

glm::dvec2 ElementMesh::position(int element, double xi, double eta) const {
    if (element < 0 || element >= element_count())
        throw Error("element " + std::to_string(element) + " is outside the mesh of " + std::to_string(element_count()));
    const int column = element % columns, row = element / columns;
    const double u = (column + 0.5 * (xi + 1.0)) / columns;  // 0 .. 1 across the columns
    const double v = (row + 0.5 * (eta + 1.0)) / rows;
    if (shape == Shape::Grid) return {2.0 * u - 1.0, 2.0 * v - 1.0};
    const double r = inner + v * (outer - inner);
    const double theta = 2.0 * kPi * u;
    return {r * std::cos(theta), r * std::sin(theta)};
}

void validate(const ElementMesh& mesh) {
    auto count = [](const char* what, int n) {
        if (n < 1 || n > 4096) throw Error(std::string(what) + " = " + std::to_string(n) + " is out of range [1, 4096]");
    };
    count("element columns", mesh.columns);
    count("element rows", mesh.rows);
    if (mesh.element_count() > (1 << 20))
        throw Error(std::to_string(mesh.element_count()) + " elements are more than the 1048576 the kit allows");
    if (mesh.shape == ElementMesh::Shape::Annulus && !(mesh.inner >= 0.0 && mesh.inner < mesh.outer && std::isfinite(mesh.outer)))
        throw Error("annulus radii " + std::to_string(mesh.inner) + " .. " + std::to_string(mesh.outer) +
                    " need 0 <= inner < outer");
}

const char* name_of(SpectralField field) { return name_of(kSpectralFieldNames, field); }
SpectralField parse_spectral_field(const std::string& name) { return parse_enum(kSpectralFieldNames, "field", name); }

double spectral_field(SpectralField field, glm::dvec2 p, double time) {
    switch (field) {
    case SpectralField::Waves:
        return std::sin(4.0 * p.x + 1.5 * time) * std::cos(3.0 * p.y - time) + 0.4 * std::sin(9.0 * glm::dot(p, p) - 2.0 * time);
    case SpectralField::Runge: return 1.0 / ((1.0 + 25.0 * p.x * p.x) * (1.0 + 25.0 * p.y * p.y));
    case SpectralField::Polynomial: return p.x * p.x * p.x * p.y * p.y - 2.0 * p.x * p.y * p.y * p.y + p.x - 0.5;
    }
    return 0.0;
}

std::vector<float> sample_element_values(const ElementMesh& mesh, SpectralField field, const std::vector<double>& nodes,
                                         double time) {
    validate(mesh);
    const std::size_t n = nodes.size();
    std::vector<float> values;
    values.reserve(static_cast<std::size_t>(mesh.element_count()) * n * n);
    for (int e = 0; e < mesh.element_count(); ++e)
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t i = 0; i < n; ++i)
                values.push_back(static_cast<float>(spectral_field(field, mesh.position(e, nodes[i], nodes[j]), time)));
    return values;
}

MeshData element_patches(const ElementMesh& mesh, int subdivisions) {
    validate(mesh);
    if (subdivisions < 1 || subdivisions > 64)
        throw Error("element subdivisions = " + std::to_string(subdivisions) + " is out of range [1, 64]");
    MeshData out;
    const int s = subdivisions;
    for (int e = 0; e < mesh.element_count(); ++e) {
        const auto first = static_cast<std::uint32_t>(out.positions.size());
        for (int b = 0; b <= s; ++b)
            for (int a = 0; a <= s; ++a) {
                // Exactly -1 and 1 at the element's edges, so an edge's fragments meet the end nodes.
                const double xi = a == s ? 1.0 : -1.0 + 2.0 * a / s;
                const double eta = b == s ? 1.0 : -1.0 + 2.0 * b / s;
                const glm::dvec2 p = mesh.position(e, xi, eta);
                out.positions.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y), 0.0f);
                out.normals.emplace_back(0.0f, 0.0f, 1.0f);
                out.texcoords.emplace_back(static_cast<float>(xi), static_cast<float>(eta));
            }
        for (int b = 0; b < s; ++b)
            for (int a = 0; a < s; ++a) {
                const std::uint32_t i0 = first + static_cast<std::uint32_t>(b * (s + 1) + a);
                const std::uint32_t i1 = i0 + 1, i2 = i0 + static_cast<std::uint32_t>(s + 1), i3 = i2 + 1;
                out.indices.insert(out.indices.end(), {i0, i1, i3, i0, i3, i2});
            }
    }
    return out;
}

}  // namespace gsv
