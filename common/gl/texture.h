#pragma once
// 2D, 2D-array and 3D textures with the sampling state the labs teach (filtering, wrap, mipmaps).
// Storage is allocated with glTexImage*, not glTexStorage*, so that everything runs on OpenGL 4.1.
#include "common/gl/gl_object.h"

namespace gsv {

enum class TexelFormat { R8, RG8, RGBA8, R32F, RG32F, RGB32F, RGBA32F, Depth24 };  // Depth24: a depth attachment

struct Sampling {
    GLenum min_filter = GL_LINEAR;   // GL_LINEAR_MIPMAP_LINEAR etc. builds the mipmap chain
    GLenum mag_filter = GL_LINEAR;
    GLenum wrap = GL_CLAMP_TO_EDGE;  // s and t, and r unless wrap_r is set
    GLenum wrap_r = 0;               // 0: as wrap. GL_REPEAT on a time axis bleeds the last frame into the first
};

bool uses_mipmaps(GLenum min_filter);
int channel_count(TexelFormat format);
bool is_float(TexelFormat format);

class Texture {
public:
    Texture() = default;
    // `texels` may be null (contents undefined); otherwise tightly packed rows, bottom row first as GL expects,
    // bytes for 8-bit formats and floats for 32F formats.
    static Texture create_2d(int width, int height, TexelFormat format, const void* texels, const Sampling& sampling = {});
    // Throws gsv::UnsupportedError when `layers` exceeds GL_MAX_ARRAY_TEXTURE_LAYERS.
    static Texture create_2d_array(int width, int height, int layers, TexelFormat format, const void* texels,
                                   const Sampling& sampling = {});
    static Texture create_3d(int width, int height, int depth, TexelFormat format, const void* texels,
                             const Sampling& sampling = {});

    void bind(int unit) const;
    void set_sampling(const Sampling& sampling);
    GLuint id() const { return name_.get(); }
    GLenum target() const { return target_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int depth() const { return depth_; }  // layers for arrays, slices for 3D, 1 for 2D
    TexelFormat format() const { return format_; }

private:
    void allocate(GLenum target, int width, int height, int depth, TexelFormat format, const void* texels,
                  const Sampling& sampling);
    TextureName name_;
    GLenum target_ = GL_TEXTURE_2D;
    int width_ = 0, height_ = 0, depth_ = 1;
    TexelFormat format_ = TexelFormat::RGBA8;
};

}  // namespace gsv
