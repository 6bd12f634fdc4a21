#pragma once
// A triangle mesh on the GPU, wired to the shader inputs of the chosen profile: the generic attributes
// aVertex/aNormal/aTexCoord0 in core, the seeds' gl_Vertex/gl_Normal/gl_MultiTexCoord0 arrays in compat.
#include "common/gl/buffer.h"
#include "common/gl/gl_object.h"
#include "common/gl/gl_version.h"
#include "common/scene/mesh_data.h"

namespace gsv {

class GpuMesh {
public:
    GpuMesh() = default;
    GpuMesh(const MeshData& mesh, Profile profile);

    void draw() const;
    std::size_t triangle_count() const { return index_count_ / 3; }
    std::size_t vertex_count() const { return vertex_count_; }

private:
    VertexArrayName vao_;
    Buffer vertices_;
    Buffer indices_;
    std::size_t index_count_ = 0;
    std::size_t vertex_count_ = 0;
};

// Two triangles covering clip space [-1,1]^2 with texture coordinates [0,1]^2: the canvas of the 2D labs.
MeshData make_fullscreen_quad();

}  // namespace gsv
