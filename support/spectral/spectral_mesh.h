#pragma once
// Lab 07's meshes of spectral elements and the fields sampled on them. An element is a quad with a map
// from the reference square [-1,1]^2 (coordinates xi, eta) into the plane; its data are the field's values
// at the (p + 1)^2 tensor-product nodes (support/spectral/lagrange.h). No GL here: the lab uploads the values and
// draws element_patches().
#include "common/scene/mesh_data.h"
#include "support/spectral/lagrange.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace gsv {

struct ElementMesh {
    enum class Shape {
        Grid,     // columns x rows square elements tiling [-1, 1]^2 (1 x 1: one element, to study it alone)
        Annulus,  // columns around x rows across the ring inner <= r <= outer: curved elements
    };
    Shape shape = Shape::Annulus;
    static constexpr EnumName<Shape> kShapeNames[] = {{Shape::Annulus, "annulus"}, {Shape::Grid, "grid"}};
    int columns = 32, rows = 4;
    double inner = 0.35, outer = 1.0;

    int element_count() const { return columns * rows; }
    // Element e = row * columns + column; throws gsv::Error for an element outside the mesh.
    glm::dvec2 position(int element, double xi, double eta) const;
};

// Throws gsv::Error naming the value unless 1 <= columns, rows <= 4096, the count is at most 1 << 20, and
// (annulus) 0 <= inner < outer.
void validate(const ElementMesh& mesh);

enum class SpectralField {
    Waves,       // travelling waves, sin and cos of x, y, r^2 and time: smooth, changing with time
    Runge,       // 1 / ((1 + 25 x^2)(1 + 25 y^2)): Runge's function; equispaced nodes diverge on it
    Polynomial,  // x^3 y^2 - 2 x y^3 + x - 0.5: degree 3 in each variable, reproduced exactly from degree 3 up
};
inline constexpr EnumName<SpectralField> kSpectralFieldNames[] = {
    {SpectralField::Waves, "waves"}, {SpectralField::Runge, "runge"}, {SpectralField::Polynomial, "polynomial"}};
const char* name_of(SpectralField field);
SpectralField parse_spectral_field(const std::string& name);  // throws naming the known ones
double spectral_field(SpectralField field, glm::dvec2 p, double time);

// The field at every element's nodes, element by element, then eta (rows of nodes), then xi fastest:
// value (e, j, i) at e (p+1)^2 + j (p+1) + i, at position(e, nodes[i], nodes[j]). Rounded to float, as the
// GPU holds them.
std::vector<float> sample_element_values(const ElementMesh& mesh, SpectralField field, const std::vector<double>& nodes,
                                         double time);

// Each element as a subdivisions x subdivisions grid of quads, 2 subdivisions^2 triangles per element, in
// element order (so a fragment's element is gl_PrimitiveID / (2 subdivisions^2)). Positions are the
// element's map (z = 0), texture coordinates the reference (xi, eta), normals +z. The subdivision only
// follows the curved geometry: the field is evaluated per fragment, not at these vertices.
MeshData element_patches(const ElementMesh& mesh, int subdivisions);

}  // namespace gsv
