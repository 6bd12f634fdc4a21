#include "common/gl/framebuffer.h"

#include "common/core/error.h"

#include <algorithm>
#include <string>

namespace gsv {

Framebuffer::Framebuffer(int width, int height, ColorFormat format, bool with_depth)
    : width_(width), height_(height), format_(format) {
    Sampling nearest{GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE};
    if (format == ColorFormat::RGBA32F && !float_renderable())
        throw UnsupportedError("a float (RGBA32F) render target on OpenGL ES needs GL_EXT_color_buffer_float, which this "
                               "driver lacks");
    color_ = Texture::create_2d(width, height, format == ColorFormat::RGBA8 ? TexelFormat::RGBA8 : TexelFormat::RGBA32F,
                                nullptr, nearest);
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    name_ = FramebufferName(fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.id(), 0);
    with_depth_ = with_depth;
    if (with_depth) {
        depth_ = Texture::create_2d(width, height, TexelFormat::Depth24, nullptr, nearest);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
    }
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw UnsupportedError("framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                               (format == ColorFormat::RGBA8 ? " RGBA8" : " RGBA32F") + " is incomplete (status 0x" +
                               [&] { char b[16]; std::snprintf(b, sizeof b, "%x", status); return std::string(b); }() + ")");
    check_gl_error("creating a framebuffer");
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, name_.get());
    glViewport(0, 0, width_, height_);
}

void Framebuffer::bind_default(int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
}

Image Framebuffer::read_rgba8() const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, name_.get());
    Image image = read_current_framebuffer(width_, height_);
    return image;
}

ImageF Framebuffer::read_rgba32f() const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, name_.get());
    ImageF image(width_, height_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, image.rgba.data());
    check_gl_error("reading back a float framebuffer");
    flip_rows(image);
    return image;
}

std::vector<float> Framebuffer::read_depth() const {
    if (!with_depth_) throw Error("this framebuffer has no depth buffer to read");
    if (gl_is_es())
        throw UnsupportedError("OpenGL ES reads back colour only, not a depth buffer: read it through LabKit::read_depth");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, name_.get());
    std::vector<float> depth(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    check_gl_error("reading back a depth buffer");
    const std::size_t row = static_cast<std::size_t>(width_);
    for (int y = 0; y < height_ / 2; ++y)
        std::swap_ranges(depth.begin() + y * row, depth.begin() + (y + 1) * row, depth.begin() + (height_ - 1 - y) * row);
    return depth;
}

bool Framebuffer::float_renderable() { return !gl_is_es() || gl_has_extension("GL_EXT_color_buffer_float"); }

Image read_current_framebuffer(int width, int height) {
    Image image(width, height);
    // RGBA8 rows are 4-byte multiples already; set the alignment anyway so no stale state can shear rows.
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    check_gl_error("reading back a framebuffer");
    flip_rows(image);
    return image;
}

}  // namespace gsv
