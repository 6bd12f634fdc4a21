#include "common/shader/shader_program.h"

#include "common/core/error.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>

namespace gsv {
namespace {

GLenum gl_stage(ShaderStage stage) {
    switch (stage) {
    case ShaderStage::Vertex: return GL_VERTEX_SHADER;
    case ShaderStage::TessControl: return GL_TESS_CONTROL_SHADER;
    case ShaderStage::TessEval: return GL_TESS_EVALUATION_SHADER;
    case ShaderStage::Geometry: return GL_GEOMETRY_SHADER;
    case ShaderStage::Fragment: return GL_FRAGMENT_SHADER;
    case ShaderStage::Compute: return GL_COMPUTE_SHADER;
    }
    return 0;
}

std::string info_log(GLuint object, bool is_program) {
    GLint length = 0;
    if (is_program) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    if (is_program) glGetProgramInfoLog(object, length, nullptr, log.data());
    else glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    while (!log.empty() && (log.back() == '\n' || log.back() == ' ')) log.pop_back();
    return log;
}

}  // namespace

ShaderProgram ShaderProgram::build(const ProgramSpec& spec, const PreprocessOptions& base_options) {
    if (spec.files.empty()) throw Error("program '" + spec.name + "' has no shader files");
    ShaderProgram program;
    std::vector<ShaderName> shaders;
    for (const auto& file : spec.files) {
        PreprocessOptions options = base_options;
        options.stage = stage_from_extension(file);
        options.defines.insert(options.defines.end(), spec.defines.begin(), spec.defines.end());
        options.generated.insert(options.generated.end(), spec.generated.begin(), spec.generated.end());
        if (options.stage == ShaderStage::Compute && options.version < GlVersion{4, 3})
            throw UnsupportedError(file.string() + ": compute shaders need OpenGL 4.3 (this run has " +
                                   options.version.str() + ")");
        const ShaderSource source = preprocess_shader(file, options);
        program.dependencies_.insert(program.dependencies_.end(), source.dependencies.begin(), source.dependencies.end());
        program.compiled_sources_.push_back(source.text);

        ShaderName shader(glCreateShader(gl_stage(options.stage)));
        const char* text = source.text.c_str();
        glShaderSource(shader.get(), 1, &text, nullptr);
        glCompileShader(shader.get());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
        if (!ok) {
            throw Error("shader compile error in " + file.string() + ":\n" +
                        translate_compile_log(info_log(shader.get(), false), source));
        }
        shaders.push_back(std::move(shader));
    }
    program.name_ = ProgramName(glCreateProgram());
    for (const auto& shader : shaders) glAttachShader(program.name_.get(), shader.get());
    if (base_options.profile == Profile::Core) {
        glBindAttribLocation(program.name_.get(), kVertexSlot, "aVertex");
        glBindAttribLocation(program.name_.get(), kNormalSlot, "aNormal");
        glBindAttribLocation(program.name_.get(), kTexCoord0Slot, "aTexCoord0");
    }
    glLinkProgram(program.name_.get());
    GLint linked = GL_FALSE;
    glGetProgramiv(program.name_.get(), GL_LINK_STATUS, &linked);
    if (!linked) {
        std::string files;
        for (const auto& f : spec.files) files += (files.empty() ? "" : " + ") + f.string();
        throw Error("shader link error in program '" + spec.name + "' (" + files + "): " +
                    info_log(program.name_.get(), true));
    }
    for (const auto& shader : shaders) glDetachShader(program.name_.get(), shader.get());
    std::sort(program.dependencies_.begin(), program.dependencies_.end());
    program.dependencies_.erase(std::unique(program.dependencies_.begin(), program.dependencies_.end()),
                                program.dependencies_.end());
    return program;
}

GLint ShaderProgram::location(const std::string& uniform) const {
    auto it = locations_.find(uniform);
    if (it != locations_.end()) return it->second;
    const GLint location = glGetUniformLocation(name_.get(), uniform.c_str());
    locations_.emplace(uniform, location);
    return location;
}

void ShaderProgram::set(const std::string& u, float v) const {
    if (GLint l = location(u); l >= 0) glUniform1f(l, v);
}
void ShaderProgram::set(const std::string& u, int v) const {
    if (GLint l = location(u); l >= 0) glUniform1i(l, v);
}
void ShaderProgram::set(const std::string& u, bool v) const {
    if (GLint l = location(u); l >= 0) glUniform1i(l, v ? 1 : 0);
}
void ShaderProgram::set(const std::string& u, const glm::vec2& v) const {
    if (GLint l = location(u); l >= 0) glUniform2fv(l, 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::vec3& v) const {
    if (GLint l = location(u); l >= 0) glUniform3fv(l, 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::vec4& v) const {
    if (GLint l = location(u); l >= 0) glUniform4fv(l, 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::mat3& v) const {
    if (GLint l = location(u); l >= 0) glUniformMatrix3fv(l, 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::mat4& v) const {
    if (GLint l = location(u); l >= 0) glUniformMatrix4fv(l, 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace gsv
