#include "support/volume/volume_box.h"

#include "common/core/error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace gsv {

VolumeBox::VolumeBox(glm::dvec3 extent) : extent_(extent) {
    for (int axis = 0; axis < 3; ++axis)
        if (!(extent[axis] > 0.0) || !std::isfinite(extent[axis])) {
            char text[160];
            std::snprintf(text, sizeof text, "volume box: extent (%g, %g, %g) needs three positive finite sides",
                          extent.x, extent.y, extent.z);
            throw Error(text);
        }
    extent_scale_ = std::max({extent.x, extent.y, extent.z}) / 2.0;
    size_ = extent / extent_scale_;
    // The largest side is 2 to the last bit, whatever rounding the division did.
    for (int axis = 0; axis < 3; ++axis)
        if (extent[axis] == 2.0 * extent_scale_) size_[axis] = 2.0;
}

glm::mat4 VolumeBox::model_from_texture_matrix() const {
    const glm::dmat4 scale = glm::scale(glm::dmat4(1.0), size_);
    return glm::mat4(glm::translate(scale, glm::dvec3(-0.5)));
}

glm::mat4 VolumeBox::texture_from_model_matrix() const {
    const glm::dmat4 shift = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5));
    return glm::mat4(glm::scale(shift, 1.0 / size_));
}

Plane VolumeBox::texture_plane(const Plane& model_plane) const {
    // n . ((t - 1/2) size) <= d  is  (n size) . t <= d + (n size) . 1/2.
    const glm::dvec3 normal = model_plane.normal * size_;
    return normalized(Plane{normal, model_plane.offset + glm::dot(normal, glm::dvec3(0.5))}, "model-space plane");
}

}  // namespace gsv
