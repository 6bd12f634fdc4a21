#include "common/shader/transform_uniforms.h"

#include "common/gl/gl.h"
#include "common/scene/mesh_data.h"

#include <glm/gtc/type_ptr.hpp>

namespace gsv {

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
