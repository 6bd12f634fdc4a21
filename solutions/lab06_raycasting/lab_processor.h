#pragma once
// What lab 06's processors share: the frame they draw (size, camera, the kit for shaders and data), the
// data their ports carry. Each declares its own typed parameters (gsv::Processor::params), which the lab adopts.
#include "common/app/app.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gpu_mesh.h"
#include "common/gl/texture.h"
#include "common/scene/mesh_data.h"
#include "support/network/processor.h"
#include "support/raycast/proxy_geometry.h"
#include "support/volume/volume.h"
#include "support/volume/volume_box.h"

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>

namespace lab06 {

// The camera and target of one frame; a network runs once per frame. Voreen passes its camera along as a
// shared property; here the lab hands every processor this before running the network.
struct FrameView {
    gsv::LabKit* kit = nullptr;
    int width = 0, height = 0;
    glm::mat4 view{1.0f}, projection{1.0f};
    glm::vec3 eye{0.0f, 0.0f, 3.0f};      // model space
    glm::vec3 forward{0.0f, 0.0f, -1.0f};  // model space, unit
    float near_distance = 0.1f;           // the projection's near plane
};

// A volume port: the voxels, their texture and their place in model space. Gradients are computed for
// the precomputed-gradient module the first time one asks (three floats a voxel, so not before).
struct VolumeData {
    gsv::Volume volume;  // values in [0, 1], as the texture holds them
    gsv::Texture texture;
    gsv::VolumeBox box{glm::dvec3(1.0)};
    const gsv::Texture& gradients();

private:
    gsv::Texture gradients_;
};

// A geometry port: a mesh whose positions are volume texture coordinates (the colours the entry and exit
// images take), with normals in model space. The proxy also keeps its polyhedron for the near-plane cap.
struct GeometryData {
    gsv::MeshData mesh;
    gsv::GpuMesh gpu;  // nothing when the mesh is empty (clip planes can remove everything)
    gsv::VolumeBox box{glm::dvec3(1.0)};
    std::optional<gsv::ProxyGeometry> proxy;
    void draw() const {
        if (!mesh.indices.empty()) gpu.draw();
    }
};

// Image ports carry a gsv::Framebuffer (RGBA32F with depth) the size of the frame.
using ImageData = gsv::Framebuffer;

class LabProcessor : public gsv::Processor {
public:
    using Processor::Processor;
    void set_view(const FrameView* view) { view_ = view; }

protected:
    const FrameView& view() const;
    gsv::LabKit& kit() const { return *view().kit; }
    // The frame's camera with `model` (a box's model_from_texture_matrix: meshes here are in texture
    // coordinates) on `program`, which must be in use.
    void set_transforms(const gsv::ShaderProgram& program, const glm::mat4& model) const;
    // A target the frame's size, rebuilt when the window is resized.
    static void fit(std::shared_ptr<ImageData>& image, const FrameView& view);

private:
    const FrameView* view_ = nullptr;
};

}  // namespace lab06
