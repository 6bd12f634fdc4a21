#include "common/gl/gpu_mesh.h"

#include "common/core/error.h"
#include "common/gl/attribute_slots.h"

#include <vector>

namespace gsv {
namespace {

struct Vertex {
    float position[3];
    float normal[3];
    float texcoord[2];
};

const void* offset_of(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

}  // namespace

GpuMesh::GpuMesh(const MeshData& mesh, Profile profile) {
    if (mesh.positions.empty() || mesh.indices.empty()) throw Error("cannot upload an empty mesh");
    std::vector<Vertex> vertices(mesh.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec3 p = mesh.positions[i];
        const glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 0, 1);
        const glm::vec2 t = i < mesh.texcoords.size() ? mesh.texcoords[i] : glm::vec2(0);
        vertices[i] = Vertex{{p.x, p.y, p.z}, {n.x, n.y, n.z}, {t.x, t.y}};
    }
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    vao_ = VertexArrayName(vao);
    glBindVertexArray(vao);
    vertices_ = Buffer::create(GL_ARRAY_BUFFER, vertices.size() * sizeof(Vertex), vertices.data());
    indices_ = Buffer::create(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.size() * sizeof(std::uint32_t), mesh.indices.data());
    vertices_.bind();
    const GLsizei stride = sizeof(Vertex);
    if (!has_fixed_function(profile)) {
        glEnableVertexAttribArray(kVertexSlot);
        glVertexAttribPointer(kVertexSlot, 3, GL_FLOAT, GL_FALSE, stride, offset_of(offsetof(Vertex, position)));
        glEnableVertexAttribArray(kNormalSlot);
        glVertexAttribPointer(kNormalSlot, 3, GL_FLOAT, GL_FALSE, stride, offset_of(offsetof(Vertex, normal)));
        glEnableVertexAttribArray(kTexCoord0Slot);
        glVertexAttribPointer(kTexCoord0Slot, 2, GL_FLOAT, GL_FALSE, stride, offset_of(offsetof(Vertex, texcoord)));
    } else {
        // The seeds' built-ins read the fixed-function arrays; a compatibility VAO records them too.
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(3, GL_FLOAT, stride, offset_of(offsetof(Vertex, position)));
        glEnableClientState(GL_NORMAL_ARRAY);
        glNormalPointer(GL_FLOAT, stride, offset_of(offsetof(Vertex, normal)));
        glClientActiveTexture(GL_TEXTURE0);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(2, GL_FLOAT, stride, offset_of(offsetof(Vertex, texcoord)));
    }
    glBindVertexArray(0);
    index_count_ = mesh.indices.size();
    vertex_count_ = mesh.positions.size();
    check_gl_error("uploading a mesh");
}

void GpuMesh::draw() const {
    glBindVertexArray(vao_.get());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(index_count_), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

MeshData make_fullscreen_quad() {
    MeshData quad;
    quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    quad.normals.assign(4, glm::vec3(0, 0, 1));
    quad.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    return quad;
}

}  // namespace gsv
