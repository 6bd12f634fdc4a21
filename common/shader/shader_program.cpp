#include "common/shader/shader_program.h"

#include "common/core/error.h"
#include "common/gl/gl_features.h"
#include "common/shader/compile_log.h"

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
        if (options.stage == ShaderStage::Compute && !allows(gl_feature::kCompute, options.profile, options.version))
            throw UnsupportedError(file.string() + " " +
                                   missing_feature_message(gl_feature::kCompute, options.profile, options.version));
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
                        translate_compile_log(info_log(shader.get(), false), source, options.stage));
        }
        shaders.push_back(std::move(shader));
    }
    program.name_ = ProgramName(glCreateProgram());
    for (const auto& shader : shaders) glAttachShader(program.name_.get(), shader.get());
    if (!has_fixed_function(base_options.profile)) {
        glBindAttribLocation(program.name_.get(), kVertexSlot, "aVertex");
        glBindAttribLocation(program.name_.get(), kNormalSlot, "aNormal");
        glBindAttribLocation(program.name_.get(), kTexCoord0Slot, "aTexCoord0");
    }
    if (!spec.captured.empty()) {
        std::vector<const char*> names;
        for (const auto& name : spec.captured) names.push_back(name.c_str());
        glTransformFeedbackVaryings(program.name_.get(), static_cast<GLsizei>(names.size()), names.data(), GL_SEPARATE_ATTRIBS);
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
    program.assign_texture_units(spec.name);
    std::sort(program.dependencies_.begin(), program.dependencies_.end());
    program.dependencies_.erase(std::unique(program.dependencies_.begin(), program.dependencies_.end()),
                                program.dependencies_.end());
    return program;
}

namespace {

bool is_sampler(GLenum type) {
    switch (type) {
    case GL_SAMPLER_1D: case GL_SAMPLER_2D: case GL_SAMPLER_3D: case GL_SAMPLER_CUBE:
    case GL_SAMPLER_1D_SHADOW: case GL_SAMPLER_2D_SHADOW: case GL_SAMPLER_1D_ARRAY: case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_1D_ARRAY_SHADOW: case GL_SAMPLER_2D_ARRAY_SHADOW: case GL_SAMPLER_2D_MULTISAMPLE:
    case GL_SAMPLER_2D_MULTISAMPLE_ARRAY: case GL_SAMPLER_CUBE_SHADOW: case GL_SAMPLER_BUFFER: case GL_SAMPLER_2D_RECT:
    case GL_SAMPLER_2D_RECT_SHADOW: case GL_INT_SAMPLER_1D: case GL_INT_SAMPLER_2D: case GL_INT_SAMPLER_3D:
    case GL_INT_SAMPLER_CUBE: case GL_INT_SAMPLER_1D_ARRAY: case GL_INT_SAMPLER_2D_ARRAY: case GL_INT_SAMPLER_BUFFER:
    case GL_INT_SAMPLER_2D_RECT: case GL_UNSIGNED_INT_SAMPLER_1D: case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_3D: case GL_UNSIGNED_INT_SAMPLER_CUBE: case GL_UNSIGNED_INT_SAMPLER_1D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY: case GL_UNSIGNED_INT_SAMPLER_BUFFER: case GL_UNSIGNED_INT_SAMPLER_2D_RECT:
        return true;
    default: return false;
    }
}

struct ActiveUniform {
    std::string name;  // as GL reports it: "uSlices[0]" for an array
    GLenum type = 0;
    GLint size = 1;
};

std::vector<ActiveUniform> active_uniforms_of(GLuint program) {
    GLint count = 0, longest = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
    std::vector<ActiveUniform> uniforms;
    std::string name(static_cast<std::size_t>(std::max(longest, 1)), '\0');
    for (GLint i = 0; i < count; ++i) {
        ActiveUniform u;
        GLsizei length = 0;
        glGetActiveUniform(program, static_cast<GLuint>(i), longest, &length, &u.size, &u.type, name.data());
        u.name.assign(name.data(), static_cast<std::size_t>(length));
        uniforms.push_back(std::move(u));
    }
    return uniforms;
}

}  // namespace

void ShaderProgram::assign_texture_units(const std::string& program_name) {
    GLint available = 0;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &available);
    // glProgramUniform is OpenGL 4.1 and ES 3.1: ES 3.0 (WebGL 2) sets a uniform on the program in use, so this one is
    // used for the moment and the one before it put back.
    GLint previous = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
    glUseProgram(name_.get());
    int next = 0;
    for (const ActiveUniform& u : active_uniforms_of(name_.get())) {
        if (!is_sampler(u.type)) continue;
        const std::string base = u.name.size() > 3 && u.name.compare(u.name.size() - 3, 3, "[0]") == 0
                                     ? u.name.substr(0, u.name.size() - 3)
                                     : u.name;
        for (GLint k = 0; k < u.size; ++k) {
            if (next >= available)
                throw UnsupportedError("program '" + program_name + "' samples more textures than this GPU's " +
                                       std::to_string(available) + " texture units");
            const std::string element = u.size > 1 || base != u.name ? base + "[" + std::to_string(k) + "]" : base;
            texture_units_[element] = next;
            if (k == 0 && element != base) texture_units_[base] = next;
            // Element locations are looked up one by one: only explicit locations are promised to be consecutive.
            glUniform1i(glGetUniformLocation(name_.get(), element.c_str()), next);
            ++next;
        }
    }
    // The one before may have been deleted while in use (a rebuild replaces it): then it went when this one took its
    // place, and nothing is left in use.
    glUseProgram(previous && glIsProgram(static_cast<GLuint>(previous)) ? static_cast<GLuint>(previous) : 0);
}

int ShaderProgram::texture_unit(const std::string& sampler) const {
    const auto it = texture_units_.find(sampler);
    return it == texture_units_.end() ? -1 : it->second;
}

void ShaderProgram::bind(const std::string& sampler, const Texture& texture) const {
    if (const int unit = texture_unit(sampler); unit >= 0) texture.bind(unit);
}

void ShaderProgram::bind(const std::string& sampler, const BufferTexture& texture) const {
    if (const int unit = texture_unit(sampler); unit >= 0) texture.bind(unit);
}

std::vector<std::string> ShaderProgram::active_uniforms() const {
    std::vector<std::string> names;
    for (const ActiveUniform& u : active_uniforms_of(name_.get()))
        if (u.name.rfind("gl_", 0) != 0) names.push_back(u.name);  // built-ins (gl_DepthRange) are GL's to set
    return names;
}

std::vector<UniformDeclaration> ShaderProgram::active_uniform_kinds() const {
    std::vector<UniformDeclaration> out;
    for (const ActiveUniform& u : active_uniforms_of(name_.get())) {
        if (u.name.rfind("gl_", 0) == 0) continue;
        UniformDeclaration d;
        const bool array = u.name.size() > 3 && u.name.compare(u.name.size() - 3, 3, "[0]") == 0;
        d.name = array ? u.name.substr(0, u.name.size() - 3) : u.name;
        if (is_sampler(u.type)) d.kind = UniformKind::Sampler;
        else if (u.size > 1) d.kind = UniformKind::Other;
        else if (u.type == GL_FLOAT) d.kind = UniformKind::Float;
        else if (u.type == GL_INT) d.kind = UniformKind::Int;
        else if (u.type == GL_BOOL) d.kind = UniformKind::Bool;
        else if (u.type == GL_FLOAT_VEC3) d.kind = UniformKind::Vec3;
        out.push_back(std::move(d));
    }
    return out;
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
