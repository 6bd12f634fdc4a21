#include "element_data.h"

#include "common/core/error.h"
#include "common/gl/gl.h"

#include <algorithm>

namespace lab07 {

void ElementData::bind(const gsv::ShaderProgram& program) const {
    std::vector<float> x(nodes.begin(), nodes.end()), w(weights.begin(), weights.end());
    glUniform1fv(program.location("uNodes[0]"), static_cast<GLsizei>(x.size()), x.data());
    glUniform1fv(program.location("uWeights[0]"), static_cast<GLsizei>(w.size()), w.data());
    program.bind("uValues", value_texture);
    program.set("uTrianglesPerElement", 2 * subdivisions * subdivisions);
    program.set("uVerticesPerElement", (subdivisions + 1) * (subdivisions + 1));
}

void update_element_data(ElementData& data, const gsv::LabKit& kit, const ElementParams& params) {
    const gsv::Params& p = kit.params();
    const gsv::Profile profile = kit.profile();
    const gsv::BufferTextureStorage storage = kit.allows(gsv::gl_feature::kBufferTextures)
                                                  ? gsv::BufferTextureStorage::Buffer
                                                  : gsv::BufferTextureStorage::Rows;
    data.mesh_made.run_if_changed(p, [&] {
        gsv::ElementMesh mesh;
        mesh.shape = params.mesh.get();
        mesh.columns = params.columns.get();
        mesh.rows = params.rows.get();
        mesh.inner = params.inner_radius.get();
        gsv::validate(mesh);
        data.mesh = mesh;
    });
    data.patches_made.run_if_changed(p, [&] {
        data.subdivisions = params.subdivisions.get();
        data.patches = gsv::GpuMesh(gsv::element_patches(data.mesh, data.subdivisions), profile);
    }, data.mesh_made.version());
    data.basis_made.run_if_changed(p, [&] {
        data.degree = params.degree.get();
        data.nodes = gsv::lagrange_nodes(params.node_set.get(), data.degree);
        data.weights = gsv::barycentric_weights(data.nodes);
    });
    data.values_made.run_if_changed(p, [&] {
        data.field = params.field.get();
        data.time = params.time.get();
        data.values = gsv::sample_element_values(data.mesh, data.field, data.nodes, data.time);
        data.value_texture = gsv::BufferTexture::create_r32f(data.values.data(), data.values.size(), storage);
        const auto [lo, hi] = std::minmax_element(data.values.begin(), data.values.end());
        data.min_value = *lo;
        data.max_value = *hi;
    }, data.mesh_made.version(), data.basis_made.version());
}

}  // namespace lab07
