#pragma once
// Move-only ownership of one GL object name; every RAII type in common/ is built on it so that a GL
// name is deleted exactly once and never copied.
#include "common/gl/gl.h"

#include <utility>

namespace gsv {

template <void (*Delete)(GLuint)>
class GlName {
public:
    GlName() = default;
    explicit GlName(GLuint name) : name_(name) {}
    ~GlName() { reset(); }
    GlName(const GlName&) = delete;
    GlName& operator=(const GlName&) = delete;
    GlName(GlName&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlName& operator=(GlName&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    GLuint get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    void reset() {
        if (name_) Delete(name_);
        name_ = 0;
    }

private:
    GLuint name_ = 0;
};

namespace gl_delete {
inline void program(GLuint n) { glDeleteProgram(n); }
inline void shader(GLuint n) { glDeleteShader(n); }
inline void texture(GLuint n) { glDeleteTextures(1, &n); }
inline void buffer(GLuint n) { glDeleteBuffers(1, &n); }
inline void framebuffer(GLuint n) { glDeleteFramebuffers(1, &n); }
inline void renderbuffer(GLuint n) { glDeleteRenderbuffers(1, &n); }
inline void vertex_array(GLuint n) { glDeleteVertexArrays(1, &n); }
inline void query(GLuint n) { glDeleteQueries(1, &n); }
}  // namespace gl_delete

using ProgramName = GlName<gl_delete::program>;
using ShaderName = GlName<gl_delete::shader>;
using TextureName = GlName<gl_delete::texture>;
using BufferName = GlName<gl_delete::buffer>;
using FramebufferName = GlName<gl_delete::framebuffer>;
using RenderbufferName = GlName<gl_delete::renderbuffer>;
using VertexArrayName = GlName<gl_delete::vertex_array>;
using QueryName = GlName<gl_delete::query>;

}  // namespace gsv
