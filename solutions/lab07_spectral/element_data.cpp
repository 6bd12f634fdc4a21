#include "element_data.h"

#include "common/core/error.h"
#include "common/gl/gl.h"

#include <algorithm>

namespace lab07 {

void ElementData::bind(const gsv::ShaderProgram& program) const {
    std::vector<float> x(nodes.begin(), nodes.end()), w(weights.begin(), weights.end());
    glUniform1fv(program.location("uNodes[0]"), static_cast<GLsizei>(x.size()), x.data());
    glUniform1fv(program.location("uWeights[0]"), static_cast<GLsizei>(w.size()), w.data());
    value_texture.bind(1);
    program.set("uValues", 1);
    program.set("uTrianglesPerElement", 2 * subdivisions * subdivisions);
}

void update_element_data(ElementData& data, const gsv::Params& p, gsv::Profile profile) {
    const bool first = !data.built;
    gsv::ElementMesh mesh;
    mesh.shape = p.get_choice("mesh") == "grid" ? gsv::ElementMesh::Shape::Grid : gsv::ElementMesh::Shape::Annulus;
    mesh.columns = p.get_int("columns");
    mesh.rows = p.get_int("rows");
    mesh.inner = p.get_float("inner_radius");
    gsv::validate(mesh);
    const int degree = p.get_int("degree");
    const gsv::NodeSet set = gsv::parse_node_set(p.get_choice("node_set"));
    const gsv::SpectralField field = gsv::parse_spectral_field(p.get_choice("field"));
    const int subdivisions = p.get_int("subdivisions");
    const double time = p.get_float("time");

    const bool geometry_changed = first || mesh.shape != data.mesh.shape || mesh.columns != data.mesh.columns ||
                                  mesh.rows != data.mesh.rows || mesh.inner != data.mesh.inner || subdivisions != data.subdivisions;
    const std::vector<double> nodes = gsv::lagrange_nodes(set, degree);
    const bool basis_changed = first || nodes != data.nodes;
    if (!geometry_changed && !basis_changed && field == data.field && time == data.time) return;

    if (geometry_changed) data.patches = gsv::GpuMesh(gsv::element_patches(mesh, subdivisions), profile);
    if (basis_changed) {
        data.nodes = nodes;
        data.weights = gsv::barycentric_weights(nodes);
    }
    data.values = gsv::sample_element_values(mesh, field, data.nodes, time);
    data.value_texture = gsv::BufferTexture::create_r32f(data.values.data(), data.values.size());
    const auto [lo, hi] = std::minmax_element(data.values.begin(), data.values.end());
    data.min_value = *lo;
    data.max_value = *hi;
    data.mesh = mesh;
    data.field = field;
    data.degree = degree;
    data.time = time;
    data.subdivisions = subdivisions;
    data.built = true;
}

}  // namespace lab07
