#pragma once
// An offscreen render target: headless runs, sweeps and the grader render into one of these, since a
// surfaceless context has no default framebuffer.
#include "common/gl/gl_object.h"
#include "common/gl/texture.h"
#include "common/image/image.h"

#include <vector>

namespace gsv {

enum class ColorFormat { RGBA8, RGBA32F };

class Framebuffer {
public:
    Framebuffer() = default;
    Framebuffer(int width, int height, ColorFormat format, bool with_depth = true);

    void bind() const;                  // binds for drawing and sets the viewport to the whole target
    static void bind_default(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    ColorFormat format() const { return format_; }
    const Texture& color() const { return color_; }
    const Texture& depth() const { return depth_; }  // a texture, so a pass can read it where GL cannot read it back
    GLuint id() const { return name_.get(); }  // for glBlitFramebuffer

    // Readbacks return row 0 = top (GL's row 0 is the bottom) and tightly packed rows.
    Image read_rgba8() const;
    ImageF read_rgba32f() const;
    // The depth buffer, width * height values in [0, 1], row 0 = top. Throws gsv::Error for a target made
    // without depth, gsv::UnsupportedError on OpenGL ES, which reads back colour only: there LabKit::read_depth
    // draws the depth into a float target first.
    std::vector<float> read_depth() const;

    // Whether RGBA32F targets can be drawn into: always on desktop GL; on OpenGL ES only with
    // GL_EXT_color_buffer_float (which WebGL 2 and every desktop GPU's ES driver offer; some phones do not).
    static bool float_renderable();

private:
    FramebufferName name_;
    Texture color_;
    Texture depth_;
    int width_ = 0, height_ = 0;
    bool with_depth_ = false;
    ColorFormat format_ = ColorFormat::RGBA8;
};

// Reads the bound read framebuffer (e.g. a window's back buffer) as RGBA8, top row first.
Image read_current_framebuffer(int width, int height);

}  // namespace gsv
