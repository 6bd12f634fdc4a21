#include "common/scene/transforms.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace gsv {

glm::vec3 OrbitCamera::eye() const {
    const float yaw = glm::radians(yaw_degrees), pitch = glm::radians(pitch_degrees);
    return distance * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
}

glm::mat4 OrbitCamera::view() const {
    // Keep the up vector off the view direction: at pitch +-90 degrees lookAt would divide by zero.
    const float pitch = glm::clamp(pitch_degrees, -89.0f, 89.0f);
    OrbitCamera clamped = *this;
    clamped.pitch_degrees = pitch;
    return glm::lookAt(clamped.eye(), glm::vec3(0.0f), glm::vec3(0, 1, 0));
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    const float near_plane = std::max(0.01f, distance - 2.0f);
    return glm::perspective(glm::radians(fov_degrees), aspect, near_plane, distance + 10.0f);
}

}  // namespace gsv
