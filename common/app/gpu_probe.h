#pragma once
// A small fragment shader drawn over a float target and read back: how the kit asks the GPU for numbers it cannot
// read directly (a depth buffer on OpenGL ES, a lab's colour function for a legend). The program is built the
// first time it is drawn, from the lab's shaders with the lab's defines, as the lab's own programs are.
#include "common/gl/gpu_mesh.h"
#include "common/image/image.h"
#include "common/shader/shader_library.h"

#include <functional>
#include <string>

namespace gsv {

class LabKit;

class GpuProbe {
public:
    // `name` names the program in compile errors; `fragment` is found as the lab's other shaders are.
    GpuProbe(std::string name, std::string fragment) : name_(std::move(name)), fragment_(std::move(fragment)) {}
    // Draws the fragment shader over a width x height RGBA32F target, after kit.use() and `set_uniforms`, and reads
    // the target back. `what` names the draw in a GL error. Leaves the bound framebuffer, viewport, depth test and
    // blending as it found them.
    ImageF draw(LabKit& kit, int width, int height, const std::function<void(const ShaderProgram&)>& set_uniforms,
                const std::string& what);

private:
    std::string name_, fragment_;
    const ShaderLibrary::Entry* program_ = nullptr;
    GpuMesh quad_;
};

}  // namespace gsv
