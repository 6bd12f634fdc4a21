#include "common/gl/buffer_texture.h"

#include "common/core/error.h"
#include "common/gl/gl.h"

#include <algorithm>
#include <string>
#include <vector>

namespace gsv {
namespace {

std::size_t gl_limit(GLenum name) {
    GLint limit = 0;
    glGetIntegerv(name, &limit);
    return limit > 0 ? static_cast<std::size_t>(limit) : 0;
}

void check_holds(std::size_t count, std::size_t limit, const std::string& what) {
    if (limit > 0 && count > limit)
        throw UnsupportedError(std::to_string(count) + " values are more than this GPU's " + what + " holds (" +
                               std::to_string(limit) + ")");
}

}  // namespace

BufferTexture BufferTexture::create_r32f(const float* values, std::size_t count, BufferTextureStorage storage) {
    if (count == 0) throw Error("a buffer texture needs at least one value");
    BufferTexture t;
    GLuint name = 0;
    glGenTextures(1, &name);
    t.texture_ = TextureName(name);
    t.count_ = count;
    t.storage_ = storage;
    if (storage == BufferTextureStorage::Buffer) {
        check_holds(count, gl_limit(GL_MAX_TEXTURE_BUFFER_SIZE), "buffer texture (GL_MAX_TEXTURE_BUFFER_SIZE)");
        t.buffer_ = Buffer::create(GL_TEXTURE_BUFFER, count * sizeof(float), values);
        glBindTexture(GL_TEXTURE_BUFFER, name);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_R32F, t.buffer_.id());
        glBindTexture(GL_TEXTURE_BUFFER, 0);
        check_gl_error("creating a buffer texture");
        return t;
    }
    check_holds(count, kRowTexels * gl_limit(GL_MAX_TEXTURE_SIZE),
                "2D texture of " + std::to_string(kRowTexels) + "-texel rows (the ES 3.0 stand-in for a buffer texture)");
    const std::size_t rows = (count + kRowTexels - 1) / kRowTexels;
    std::vector<float> padded(rows * kRowTexels, 0.0f);
    std::copy(values, values + count, padded.begin());
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, kRowTexels, static_cast<GLsizei>(rows), 0, GL_RED, GL_FLOAT, padded.data());
    // Read with texelFetch only; a float texture without mipmaps must still not ask for them to be complete.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    check_gl_error("creating a buffer texture's rows");
    return t;
}

void BufferTexture::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(storage_ == BufferTextureStorage::Buffer ? GL_TEXTURE_BUFFER : GL_TEXTURE_2D, texture_.get());
}

}  // namespace gsv
