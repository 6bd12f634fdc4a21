#include "common/gl/buffer.h"

#include "common/core/error.h"

#include <string>

namespace gsv {

Buffer Buffer::create(GLenum target, std::size_t bytes, const void* data, GLenum usage) {
    if (target == GL_SHADER_STORAGE_BUFFER && !(gl_is_es() ? GLAD_GL_ES_VERSION_3_1 : GLAD_GL_VERSION_4_3))
        throw UnsupportedError("shader storage buffers need OpenGL 4.3 or OpenGL ES 3.1");
    Buffer buffer;
    GLuint name = 0;
    glGenBuffers(1, &name);
    buffer.name_ = BufferName(name);
    buffer.target_ = target;
    buffer.size_ = bytes;
    glBindBuffer(target, name);
    glBufferData(target, static_cast<GLsizeiptr>(bytes), data, usage);
    check_gl_error("allocating a buffer");
    return buffer;
}

void Buffer::bind_base(GLuint index) const {
    glBindBufferBase(target_, index, name_.get());
}

void Buffer::upload(std::size_t offset, std::size_t bytes, const void* data) {
    if (offset + bytes > size_)
        throw Error("buffer upload of " + std::to_string(bytes) + " bytes at offset " + std::to_string(offset) +
                    " overruns a buffer of " + std::to_string(size_));
    bind();
    glBufferSubData(target_, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void* Buffer::map_write_invalidate() {
    bind();
    void* p = glMapBufferRange(target_, 0, static_cast<GLsizeiptr>(size_),
                               GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
    if (!p) throw Error("glMapBufferRange refused to map a buffer of " + std::to_string(size_) + " bytes for writing");
    return p;
}

void* Buffer::map_read() {
    bind();
    void* p = glMapBufferRange(target_, 0, static_cast<GLsizeiptr>(size_), GL_MAP_READ_BIT);
    if (!p) throw Error("glMapBufferRange refused to map a buffer of " + std::to_string(size_) + " bytes for reading");
    return p;
}

void Buffer::unmap() {
    bind();
    if (glUnmapBuffer(target_) != GL_TRUE) throw Error("buffer contents were lost while mapped (glUnmapBuffer)");
}

}  // namespace gsv
