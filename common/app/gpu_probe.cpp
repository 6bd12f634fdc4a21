#include "common/app/gpu_probe.h"

#include "common/app/app.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/gl/saved_draw_state.h"

namespace gsv {

ImageF GpuProbe::draw(LabKit& kit, int width, int height, const std::function<void(const ShaderProgram&)>& set_uniforms,
                      const std::string& what) {
    if (!program_) {
        program_ = &kit.program(name_, {"gsv/fullscreen.vert", fragment_});
        quad_ = GpuMesh(make_fullscreen_quad(), kit.profile());
    }
    const Framebuffer target(width, height, ColorFormat::RGBA32F, false);
    const SavedDrawState saved;
    target.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    const ShaderProgram& program = kit.use(*program_);
    if (set_uniforms) set_uniforms(program);
    quad_.draw();
    check_gl_error(what.c_str());
    return target.read_rgba32f();
}

}  // namespace gsv
