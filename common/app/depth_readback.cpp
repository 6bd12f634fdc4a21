#include "common/app/depth_readback.h"

#include "common/app/app.h"

namespace gsv {

std::vector<float> DepthReadback::read(LabKit& kit, const Framebuffer& target) {
    if (kit.profile() != Profile::Es) return target.read_depth();
    if (!target.depth().id()) return target.read_depth();  // the same "no depth buffer" error
    const ImageF pixels = probe_.draw(kit, target.width(), target.height(),
                                      [&](const ShaderProgram& program) { program.bind("uDepth", target.depth()); },
                                      "drawing a depth buffer into a float target");
    std::vector<float> depth(static_cast<std::size_t>(target.width()) * static_cast<std::size_t>(target.height()));
    for (std::size_t i = 0; i < depth.size(); ++i) depth[i] = pixels.rgba[4 * i];
    return depth;
}

}  // namespace gsv
