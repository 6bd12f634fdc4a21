#pragma once
// A linked GLSL program built from shader files through the kit's preprocessor, with uniforms set by name.
// Texture units are the program's business, not the lab's: at link time every active sampler (each element of a
// sampler array) gets a unit of its own, so `program.bind("uVolume", texture)` is all a lab writes. Two samplers
// of different types on one unit fail every draw; this cannot happen.
#include "common/gl/attribute_slots.h"
#include "common/gl/buffer_texture.h"
#include "common/gl/gl_object.h"
#include "common/gl/texture.h"
#include "common/shader/shader_source.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace gsv {

// What an active uniform holds, as far as a parameter's value could be set on it (common/shader/param_uniforms.h).
enum class UniformKind { Float, Int, Bool, Vec3, Sampler, Other };
struct UniformDeclaration {
    std::string name;  // an array's without its "[0]"
    UniformKind kind = UniformKind::Other;  // an array of more than one element: Other, a sampler array: Sampler
};

struct ProgramSpec {
    std::string name;                              // for messages: "gooch"
    std::vector<std::filesystem::path> files;      // one per stage; the stage comes from the extension
    std::vector<ShaderDefine> defines;
    std::vector<GeneratedFile> generated{};        // in-memory include files, after the options' own
    // Vertex outputs written to buffers by transform feedback, one buffer each (binding i: captured[i]): a step of a
    // simulation where there are no compute shaders (OpenGL ES 3.0, WebGL 2).
    std::vector<std::string> captured{};
};

class ShaderProgram {
public:
    ShaderProgram() = default;
    // Preprocesses, compiles and links; throws gsv::Error with the driver's log mapped to file:line.
    static ShaderProgram build(const ProgramSpec& spec, const PreprocessOptions& options);

    void use() const { glUseProgram(name_.get()); }
    GLuint id() const { return name_.get(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    const std::vector<std::filesystem::path>& dependencies() const { return dependencies_; }
    // The exact text each stage was compiled from, in the order of the spec's files.
    const std::vector<std::string>& compiled_sources() const { return compiled_sources_; }

    // -1 when the program has no active uniform of that name (the GLSL compiler drops unused ones).
    GLint location(const std::string& uniform) const;
    bool has(const std::string& uniform) const { return location(uniform) >= 0; }
    // Setters act on the program in use and skip uniforms the program does not have.
    void set(const std::string& uniform, float value) const;
    void set(const std::string& uniform, int value) const;
    void set(const std::string& uniform, bool value) const;
    void set(const std::string& uniform, const glm::vec2& value) const;
    void set(const std::string& uniform, const glm::vec3& value) const;
    void set(const std::string& uniform, const glm::vec4& value) const;
    void set(const std::string& uniform, const glm::mat3& value) const;
    void set(const std::string& uniform, const glm::mat4& value) const;

    // Binds `texture` to the unit the program gave sampler `sampler` ("uFlowSlices[3]" for an array element);
    // skips a sampler the program does not have, as set() does.
    void bind(const std::string& sampler, const Texture& texture) const;
    void bind(const std::string& sampler, const BufferTexture& texture) const;
    // The texture unit of a sampler, -1 when the program has no such sampler.
    int texture_unit(const std::string& sampler) const;
    // The names of the program's active uniforms as GL reports them ("uNodes[0]" for an array), samplers included,
    // built-ins (gl_DepthRange) left out.
    std::vector<std::string> active_uniforms() const;
    // The same, each with what it holds.
    std::vector<UniformDeclaration> active_uniform_kinds() const;

private:
    void assign_texture_units(const std::string& program_name);
    ProgramName name_;
    std::vector<std::filesystem::path> dependencies_;
    std::vector<std::string> compiled_sources_;
    mutable std::unordered_map<std::string, GLint> locations_;
    std::unordered_map<std::string, int> texture_units_;
};

}  // namespace gsv
