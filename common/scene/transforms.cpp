#include "common/scene/transforms.h"

#include "common/gl/gl.h"
#include "common/scene/mesh_data.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

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

void apply_transforms(const ShaderProgram& program, const Transforms& t, Profile profile) {
    const glm::mat4 model_view = t.view * t.model;
    if (!has_fixed_function(profile)) {
        program.set("uModelViewProjectionMatrix", t.projection * model_view);
        program.set("uModelViewMatrix", model_view);
        program.set("uProjectionMatrix", t.projection);
        program.set("uNormalMatrix", normal_matrix(model_view));
    } else {
        // gl_NormalMatrix is derived by GL from the modelview matrix: the same inverse-transpose.
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(glm::value_ptr(t.projection));
        glMatrixMode(GL_MODELVIEW);
        glLoadMatrixf(glm::value_ptr(model_view));
    }
}

}  // namespace gsv
