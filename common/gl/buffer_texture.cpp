#include "common/gl/buffer_texture.h"

#include "common/core/error.h"
#include "common/gl/gl.h"

#include <string>

namespace gsv {

BufferTexture BufferTexture::create_r32f(const float* values, std::size_t count) {
    if (count == 0) throw Error("a buffer texture needs at least one value");
    GLint limit = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &limit);
    if (limit > 0 && count > static_cast<std::size_t>(limit))
        throw UnsupportedError(std::to_string(count) + " values are more than this GPU's buffer texture holds (GL_MAX_TEXTURE_BUFFER_SIZE = " +
                               std::to_string(limit) + ")");
    BufferTexture t;
    t.buffer_ = Buffer::create(GL_TEXTURE_BUFFER, count * sizeof(float), values);
    GLuint name = 0;
    glGenTextures(1, &name);
    t.texture_ = TextureName(name);
    glBindTexture(GL_TEXTURE_BUFFER, name);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_R32F, t.buffer_.id());
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    t.count_ = count;
    check_gl_error("creating a buffer texture");
    return t;
}

void BufferTexture::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_BUFFER, texture_.get());
}

}  // namespace gsv
