#include "common/app/depth_readback.h"

#include "common/app/app.h"
#include "common/gl/gl.h"
#include "common/gl/saved_draw_state.h"

namespace gsv {

std::vector<float> DepthReadback::read(LabKit& kit, const Framebuffer& target) {
    if (kit.profile() != Profile::Es) return target.read_depth();
    if (!target.depth().id()) return target.read_depth();  // the same "no depth buffer" error
    if (!program_) {
        program_ = &kit.program("depth readback", {"gsv/fullscreen.vert", "gsv/depth_to_color.frag"});
        quad_ = GpuMesh(make_fullscreen_quad(), kit.profile());
    }
    const Framebuffer copy(target.width(), target.height(), ColorFormat::RGBA32F, false);
    ImageF pixels;
    {
        const SavedDrawState saved;
        copy.bind();
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        const ShaderProgram& program = kit.use(*program_);
        program.bind("uDepth", target.depth());
        quad_.draw();
        check_gl_error("drawing a depth buffer into a float target");
        pixels = copy.read_rgba32f();
    }
    std::vector<float> depth(static_cast<std::size_t>(target.width()) * static_cast<std::size_t>(target.height()));
    for (std::size_t i = 0; i < depth.size(); ++i) depth[i] = pixels.rgba[4 * i];
    return depth;
}

}  // namespace gsv
