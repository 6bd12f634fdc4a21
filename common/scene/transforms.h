#pragma once
// Model, view and projection for a draw, and the orbit camera every 3D lab is looked at with: matrices only, no GL
// (common/shader/transform_uniforms.h hands them to a program).
#include <glm/glm.hpp>

namespace gsv {

struct Transforms {
    glm::mat4 model{1.0f};
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
};

// An orbit camera around the origin, the way every 3D lab is looked at.
struct OrbitCamera {
    float yaw_degrees = 30.0f;
    float pitch_degrees = 20.0f;
    float distance = 3.0f;
    float fov_degrees = 40.0f;
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
    glm::vec3 eye() const;
};

}  // namespace gsv
