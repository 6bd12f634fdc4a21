#include "common/gl/texture.h"

#include "common/core/error.h"

#include <string>

namespace gsv {
namespace {

struct GlFormat {
    GLint internal;
    GLenum format;
    GLenum type;
};

GlFormat gl_format(TexelFormat format) {
    switch (format) {
    case TexelFormat::R8: return {GL_R8, GL_RED, GL_UNSIGNED_BYTE};
    case TexelFormat::RG8: return {GL_RG8, GL_RG, GL_UNSIGNED_BYTE};
    case TexelFormat::RGBA8: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
    case TexelFormat::R32F: return {GL_R32F, GL_RED, GL_FLOAT};
    case TexelFormat::RG32F: return {GL_RG32F, GL_RG, GL_FLOAT};
    case TexelFormat::RGB32F: return {GL_RGB32F, GL_RGB, GL_FLOAT};
    case TexelFormat::RGBA32F: return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
    case TexelFormat::Depth24: return {GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT};
    }
    return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
}

}  // namespace

bool uses_mipmaps(GLenum min_filter) {
    return min_filter == GL_NEAREST_MIPMAP_NEAREST || min_filter == GL_NEAREST_MIPMAP_LINEAR ||
           min_filter == GL_LINEAR_MIPMAP_NEAREST || min_filter == GL_LINEAR_MIPMAP_LINEAR;
}

int channel_count(TexelFormat format) {
    switch (format) {
    case TexelFormat::R8: case TexelFormat::R32F: case TexelFormat::Depth24: return 1;
    case TexelFormat::RG8: case TexelFormat::RG32F: return 2;
    case TexelFormat::RGB32F: return 3;
    case TexelFormat::RGBA8: case TexelFormat::RGBA32F: return 4;
    }
    return 4;
}

bool is_float(TexelFormat format) {
    return format == TexelFormat::R32F || format == TexelFormat::RG32F || format == TexelFormat::RGB32F ||
           format == TexelFormat::RGBA32F;
}

void Texture::allocate(GLenum target, int width, int height, int depth, TexelFormat format, const void* texels,
                       const Sampling& sampling) {
    if (width <= 0 || height <= 0 || depth <= 0)
        throw Error("texture size " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                    std::to_string(depth) + " is not positive");
    GLint max_size = 0;
    glGetIntegerv(target == GL_TEXTURE_3D ? GL_MAX_3D_TEXTURE_SIZE : GL_MAX_TEXTURE_SIZE, &max_size);
    if (width > max_size || height > max_size || (target == GL_TEXTURE_3D && depth > max_size))
        throw UnsupportedError("texture size " + std::to_string(width) + "x" + std::to_string(height) +
                               " exceeds this GL's limit of " + std::to_string(max_size));
    GLuint name = 0;
    glGenTextures(1, &name);
    name_ = TextureName(name);
    target_ = target;
    width_ = width;
    height_ = height;
    depth_ = depth;
    format_ = format;
    const GlFormat f = gl_format(format);
    glBindTexture(target, name);
    // Rows of R8 and RG8 data are rarely 4-byte aligned; the kit's arrays are always tightly packed.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (target == GL_TEXTURE_2D)
        glTexImage2D(target, 0, f.internal, width, height, 0, f.format, f.type, texels);
    else
        glTexImage3D(target, 0, f.internal, width, height, depth, 0, f.format, f.type, texels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    check_gl_error("allocating a texture");
    set_sampling(sampling);
}

Texture Texture::create_2d(int width, int height, TexelFormat format, const void* texels, const Sampling& sampling) {
    Texture t;
    t.allocate(GL_TEXTURE_2D, width, height, 1, format, texels, sampling);
    return t;
}

Texture Texture::create_2d_array(int width, int height, int layers, TexelFormat format, const void* texels,
                                 const Sampling& sampling) {
    GLint max_layers = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
    if (layers > max_layers)
        throw UnsupportedError("a 2D texture array of " + std::to_string(layers) +
                               " layers exceeds GL_MAX_ARRAY_TEXTURE_LAYERS = " + std::to_string(max_layers));
    Texture t;
    t.allocate(GL_TEXTURE_2D_ARRAY, width, height, layers, format, texels, sampling);
    return t;
}

Texture Texture::create_3d(int width, int height, int depth, TexelFormat format, const void* texels,
                           const Sampling& sampling) {
    Texture t;
    t.allocate(GL_TEXTURE_3D, width, height, depth, format, texels, sampling);
    return t;
}

void Texture::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(target_, name_.get());
}

void Texture::set_sampling(const Sampling& sampling) {
    const bool linear = sampling.mag_filter == GL_LINEAR || sampling.min_filter != GL_NEAREST;
    // ES filters 32-bit float textures only with this extension; without it a linear lookup reads an incomplete
    // texture (black), which must not pass for a picture.
    if (is_float(format_) && linear && gl_is_es() && !gl_has_extension("GL_OES_texture_float_linear"))
        throw UnsupportedError("linear filtering of a float texture on OpenGL ES needs GL_OES_texture_float_linear, "
                               "which this driver lacks");
    glBindTexture(target_, name_.get());
    glTexParameteri(target_, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(sampling.min_filter));
    glTexParameteri(target_, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(sampling.mag_filter));
    glTexParameteri(target_, GL_TEXTURE_WRAP_S, static_cast<GLint>(sampling.wrap));
    glTexParameteri(target_, GL_TEXTURE_WRAP_T, static_cast<GLint>(sampling.wrap));
    if (target_ != GL_TEXTURE_2D)
        glTexParameteri(target_, GL_TEXTURE_WRAP_R, static_cast<GLint>(sampling.wrap_r ? sampling.wrap_r : sampling.wrap));
    if (uses_mipmaps(sampling.min_filter)) glGenerateMipmap(target_);
    check_gl_error("setting texture sampling");
}

}  // namespace gsv
