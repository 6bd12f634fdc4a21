#pragma once
// The GL half of LIC's optional contrast (lic_contrast.h): the LIC image is drawn into a float target, read back,
// its tone curve found on the CPU, and the image drawn through the curve (shaders/gsv/tone_curve.frag) where it was
// meant to go. With the contrast off the LIC is drawn straight there: no target, no readback, no second pass.
#include "common/app/app.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gpu_mesh.h"
#include "common/gl/texture.h"
#include "support/flow/lic_contrast.h"

#include <functional>

namespace gsv {

class LicContrastPass {
public:
    // Calls draw_lic() to draw the LIC image over the whole bound framebuffer (frame.width x frame.height), with the
    // contrast asked for; `quad` is a full-screen quad (make_fullscreen_quad). Leaves the framebuffer that was bound
    // bound, with its viewport.
    void draw(LabKit& kit, const Frame& frame, LicContrast contrast, const GpuMesh& quad,
              const std::function<void()>& draw_lic);
    // The curve of the last frame drawn with a contrast (the identity before any): for tests and the lab sheet's
    // numbers.
    const ToneCurve& curve() const { return curve_; }

private:
    const ShaderLibrary::Entry* program_ = nullptr;  // built the first time a contrast is asked for
    Framebuffer target_;
    Texture curve_texture_;
    ToneCurve curve_;
};

}  // namespace gsv
