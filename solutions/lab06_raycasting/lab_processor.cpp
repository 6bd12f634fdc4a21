#include "lab_processor.h"

#include "common/core/error.h"
#include "common/scene/transforms.h"
#include "support/volume/sobel_gradient.h"

#include <vector>

namespace lab06 {

const gsv::Texture& VolumeData::gradients() {
    if (!gradients_.id()) {
        // Computed once, so it can afford the smoother 27-voxel Sobel operator.
        const std::vector<float> g = gsv::sobel_gradient_volume(volume);
        gradients_ = gsv::Texture::create_3d(volume.nx, volume.ny, volume.nz, gsv::TexelFormat::RGB32F, g.data());
    }
    return gradients_;
}

const FrameView& LabProcessor::view() const {
    if (!view_ || !view_->kit) throw gsv::Error(describe() + " has no frame to draw (set_view was not called)");
    return *view_;
}

void LabProcessor::set_transforms(const gsv::ShaderProgram& program, const glm::mat4& model) const {
    gsv::Transforms t;
    t.model = model;
    t.view = view().view;
    t.projection = view().projection;
    kit().set_transforms(program, t);
}

void LabProcessor::fit(std::shared_ptr<ImageData>& image, const FrameView& view) {
    if (!image || image->width() != view.width || image->height() != view.height)
        image = std::make_shared<ImageData>(view.width, view.height, gsv::ColorFormat::RGBA32F, true);
}

}  // namespace lab06
