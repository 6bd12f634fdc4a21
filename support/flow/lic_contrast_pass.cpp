#include "support/flow/lic_contrast_pass.h"

#include "common/gl/gl.h"

#include <cstddef>
#include <vector>

namespace gsv {
namespace {

// The grey a tone curve is found from: Rec. 709 luminance, the grey itself for a grey image.
std::vector<float> grey_levels(const ImageF& image) {
    std::vector<float> grey(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
    for (std::size_t i = 0; i < grey.size(); ++i) {
        const float* p = &image.rgba[4 * i];
        grey[i] = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
    }
    return grey;
}

}  // namespace

void LicContrastPass::draw(LabKit& kit, const Frame& frame, LicContrast contrast, const GpuMesh& quad,
                           const std::function<void()>& draw_lic) {
    if (contrast == LicContrast::Off) {
        draw_lic();
        return;
    }
    GLint previous_draw = 0, previous_read = 0, viewport[4];
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_draw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous_read);
    glGetIntegerv(GL_VIEWPORT, viewport);

    if (target_.width() != frame.width || target_.height() != frame.height)
        target_ = Framebuffer(frame.width, frame.height, ColorFormat::RGBA32F, false);
    target_.bind();
    draw_lic();
    curve_ = make_tone_curve(grey_levels(target_.read_rgba32f()), contrast);
    // The identity still goes through the pass, as one value repeated: the image lands where it was meant to.
    const std::vector<float> values = curve_.identity() ? std::vector<float>{0.0f, 0.0f} : curve_.values;
    curve_texture_ = Texture::create_2d(static_cast<int>(values.size()), 1, TexelFormat::R32F, values.data(),
                                        Sampling{GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE});

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previous_draw));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous_read));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    if (!program_) program_ = &kit.program("tone_curve", {"gsv/fullscreen.vert", "gsv/tone_curve.frag"});
    const ShaderProgram& program = kit.use(*program_);
    program.bind("uImage", target_.color());
    program.bind("uToneCurve", curve_texture_);
    program.set("uToneRange", curve_.identity() ? glm::vec2(0.0f) : glm::vec2(curve_.low, curve_.high));
    glDisable(GL_DEPTH_TEST);
    quad.draw();
}

}  // namespace gsv
