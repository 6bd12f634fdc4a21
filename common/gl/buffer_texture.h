#pragma once
// A buffer texture (GL_TEXTURE_BUFFER, samplerBuffer in GLSL, core since GL 3.1, so on macOS's 4.1 too):
// a plain array of floats in GPU memory that a shader reads with texelFetch(sampler, index). Lab 07 keeps
// every element's node values in one, so a draw of thousands of elements needs no texture per element.
#include "common/gl/buffer.h"
#include "common/gl/gl_object.h"

#include <cstddef>

namespace gsv {

class BufferTexture {
public:
    BufferTexture() = default;
    // `count` floats, one R32F texel each. Throws gsv::UnsupportedError when `count` exceeds
    // GL_MAX_TEXTURE_BUFFER_SIZE (the driver's limit, at least 65536), gsv::Error for no values.
    static BufferTexture create_r32f(const float* values, std::size_t count);

    void bind(int unit) const;  // to GL_TEXTURE_BUFFER on that texture unit
    std::size_t size() const { return count_; }
    std::size_t bytes() const { return buffer_.size(); }

private:
    Buffer buffer_;
    TextureName texture_;
    std::size_t count_ = 0;
};

}  // namespace gsv
