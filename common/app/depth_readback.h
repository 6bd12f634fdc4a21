#pragma once
// Reads a framebuffer's depth back in every profile: desktop GL reads it directly; OpenGL ES reads back colour
// only, so there the depth texture is drawn into a float target (gsv/depth_to_color.frag) and that is read.
// The program is built the first time depth is asked for on ES.
#include "common/app/gpu_probe.h"
#include "common/gl/framebuffer.h"

#include <vector>

namespace gsv {

class LabKit;

class DepthReadback {
public:
    // width * height values in [0, 1], row 0 = top, as Framebuffer::read_depth. Leaves the bound framebuffer,
    // viewport, depth test and blending as it found them.
    std::vector<float> read(LabKit& kit, const Framebuffer& target);

private:
    GpuProbe probe_{"depth readback", "gsv/depth_to_color.frag"};
};

}  // namespace gsv
