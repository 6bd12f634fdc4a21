#pragma once
// Lab 06's image processors: the opaque geometry's own image, and the canvas that puts the ray caster's
// image over it and over the background.
#include "lab_processor.h"

#include "common/gl/gpu_mesh.h"
#include "common/shader/shader_library.h"

namespace lab06 {

class GeometryRenderer final : public LabProcessor {
public:
    GeometryRenderer();
    void process() override;

private:
    gsv::Param<glm::vec3> geometry_color_;
    const gsv::ShaderLibrary::Entry* program_ = nullptr;
    std::shared_ptr<ImageData> image_;
};

class Canvas final : public LabProcessor {
public:
    Canvas();
    void process() override;
    const std::shared_ptr<ImageData>& image() const { return image_; }  // kept when a later run fails

private:
    gsv::Param<glm::vec3> background_;
    const gsv::ShaderLibrary::Entry* program_ = nullptr;
    gsv::GpuMesh quad_;
    std::shared_ptr<ImageData> image_;
};

}  // namespace lab06
