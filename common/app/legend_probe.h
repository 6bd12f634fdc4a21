#pragma once
// A legend's colours sampled from the lab's own shaders, so the legend shows what its pictures draw and there is
// no second copy of a colour map in C++ to drift from the GLSL. A lab writes a small probe shader that includes
// "gsv/legend_probe.glsl" and its colour function, and writes that function's colour for legendValue():
//
//   #include "gsv/legend_probe.glsl"
//   #include "palette.glsl"                 // the lab's own, with the colour function its pictures use
//   out vec4 fColor;
//   void main() { fColor = vec4(valueColor(legendValue()), 1.0); }
//
// The probe draws one row of pixels, one per value, and reads them back. Its program is built the first time a
// legend is asked for (a grader's render never pays for it), from the lab's shaders with the lab's defines, and is
// rebuilt with them (hot reload, compile-time parameters): an edit to the colour function shows in the legend.
#include "common/app/app.h"
#include "common/app/gpu_probe.h"
#include "common/image/legend.h"

#include <functional>
#include <string>
#include <vector>

namespace gsv {

class LegendProbe {
public:
    // `fragment`: the lab's probe shader, found as its other shaders are.
    explicit LegendProbe(const std::string& fragment) : probe_("legend probe (" + fragment + ")", fragment) {}

    // The colour the probe writes at each value, clamped to [0, 1]; NaN comes back magenta, as in a render.
    // kit.use() sets the lab's parameters as uniforms; `set_uniforms` sets the rest (a range the lab computes).
    // Leaves the bound framebuffer, viewport, depth test and blending as it found them.
    std::vector<LegendColor> colors(LabKit& kit, const std::vector<double>& values,
                                    const std::function<void(const ShaderProgram&)>& set_uniforms = {});
    // `count` stops evenly spaced over [min, max], ends included.
    std::vector<LegendStop> ramp(LabKit& kit, double min, double max, int count,
                                 const std::function<void(const ShaderProgram&)>& set_uniforms = {});

private:
    GpuProbe probe_;
};

}  // namespace gsv
