#include "lab_processor.h"

#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/scene/transforms.h"
#include "support/volume/sobel_gradient.h"

#include <sstream>
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

double LabProcessor::number(const std::string& name, double min, double max) const {
    const std::string& text = property(name);
    const std::optional<double> value = gsv::parse_finite_number(text);
    if (!value || *value < min || *value > max) {
        std::ostringstream range;
        range << "[" << min << ", " << max << "]";
        throw gsv::Error(this->name() + "." + name + " = '" + text + "' is not a number in " + range.str());
    }
    return *value;
}

bool LabProcessor::flag(const std::string& name) const {
    const std::string& text = property(name);
    if (text == "on" || text == "true" || text == "1") return true;
    if (text == "off" || text == "false" || text == "0") return false;
    throw gsv::Error(this->name() + "." + name + " = '" + text + "' is not on or off");
}

glm::vec3 LabProcessor::vec3(const std::string& name) const {
    const std::string& text = property(name);
    glm::vec3 v(0.0f);
    std::stringstream in(text);
    std::string part;
    int count = 0;
    while (std::getline(in, part, ',')) {
        const std::optional<double> x = gsv::parse_finite_number(part);
        if (!x || count == 3) {
            count = 4;
            break;
        }
        v[count++] = static_cast<float>(*x);
    }
    if (count != 3) throw gsv::Error(this->name() + "." + name + " = '" + text + "' is not three numbers x,y,z");
    return v;
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
