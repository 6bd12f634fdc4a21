#pragma once
// A buffer texture (GL_TEXTURE_BUFFER, samplerBuffer in GLSL, core since GL 3.1, so on macOS's 4.1 too):
// a plain array of floats in GPU memory that a shader reads with bufferFetch(sampler, index)
// (shaders/gsv/buffer_fetch.glsl). Lab 07 keeps every element's node values in one, so a draw of thousands
// of elements needs no texture per element.
// OpenGL ES has buffer textures only from 3.2 (WebGL 2 not at all): there the same values are the rows of a
// 2D R32F texture kRowTexels wide, and bufferFetch turns the index into a row and a column.
#include "common/gl/buffer.h"
#include "common/gl/gl_object.h"

#include <cstddef>

namespace gsv {

enum class BufferTextureStorage {
    Buffer,  // GL_TEXTURE_BUFFER over a buffer object
    Rows,    // a GL_TEXTURE_2D of kRowTexels columns, the last row padded: ES 3.0 and 3.1
};

class BufferTexture {
public:
    // Must match kBufferRowTexels in shaders/gsv/buffer_fetch.glsl; ES 3.0 guarantees 2D textures this wide.
    static constexpr int kRowTexels = 2048;

    BufferTexture() = default;
    // `count` floats, one R32F texel each. Throws gsv::UnsupportedError when `count` exceeds what the storage
    // holds (GL_MAX_TEXTURE_BUFFER_SIZE, at least 65536; rows: kRowTexels x GL_MAX_TEXTURE_SIZE), gsv::Error for
    // no values.
    static BufferTexture create_r32f(const float* values, std::size_t count,
                                     BufferTextureStorage storage = BufferTextureStorage::Buffer);

    void bind(int unit) const;  // to GL_TEXTURE_BUFFER (rows: GL_TEXTURE_2D) on that texture unit
    std::size_t size() const { return count_; }
    std::size_t bytes() const { return count_ * sizeof(float); }
    BufferTextureStorage storage() const { return storage_; }

private:
    Buffer buffer_;
    TextureName texture_;
    std::size_t count_ = 0;
    BufferTextureStorage storage_ = BufferTextureStorage::Buffer;
};

}  // namespace gsv
