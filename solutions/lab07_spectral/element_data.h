#pragma once
// Lab 07's GPU side of a spectral element mesh: the basis (nodes and barycentric weights, 2 (p + 1) uniform
// floats whatever the number of elements), every element's node values in one buffer texture, and the
// patches that place the elements. Rebuilt when the mesh, field, degree, node set or time changes.
#include "common/app/app.h"
#include "common/params/change_tracker.h"
#include "common/gl/buffer_texture.h"
#include "common/gl/gpu_mesh.h"
#include "common/shader/shader_program.h"
#include "support/spectral/spectral_mesh.h"

#include <string>
#include <vector>

namespace lab07 {

// The lab's parameters the element data are made from: declared by the lab (lab.cpp), which keeps them.
struct ElementParams {
    gsv::EnumParam<gsv::ElementMesh::Shape> mesh;
    gsv::Param<int> columns, rows;
    gsv::Param<float> inner_radius;
    gsv::EnumParam<gsv::SpectralField> field;
    gsv::Param<int> degree;
    gsv::EnumParam<gsv::NodeSet> node_set;
    gsv::Param<int> subdivisions;
    gsv::Param<float> time;
};

struct ElementData {
    gsv::ElementMesh mesh;
    gsv::SpectralField field = gsv::SpectralField::Waves;
    int degree = 1;
    double time = 0;
    std::vector<double> nodes, weights;
    std::vector<float> values;  // as uploaded
    float min_value = 0, max_value = 0;
    int subdivisions = 1;

    gsv::BufferTexture value_texture;
    gsv::GpuMesh patches;

    // Each part is remade only when what it was made from changed: moving the time resamples the values only.
    gsv::ChangeTracker mesh_made, patches_made, basis_made, values_made;

    std::size_t basis_bytes() const { return nodes.size() * 2 * sizeof(float); }
    // Sets the basis uniforms (uNodes, uWeights), binds the values (uValues), sets the spectral uniforms;
    // `program` in use.
    void bind(const gsv::ShaderProgram& program) const;
};

// The mesh, field, nodes and values the parameters describe, uploaded; what has not changed is kept. Throws
// gsv::Error naming a bad mesh, gsv::UnsupportedError for more values than a buffer texture holds. The values
// go into a buffer texture where the run has them, else into its stand-in (OpenGL ES 3.0, 3.1: rows of a 2D
// texture, gsv/buffer_fetch.glsl).
void update_element_data(ElementData& data, const gsv::LabKit& kit, const ElementParams& params);

}  // namespace lab07
