#pragma once
// A linked GLSL program built from shader files through the kit's preprocessor, with uniforms set by name.
#include "common/gl/gl_object.h"
#include "common/shader/shader_source.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace gsv {

// The attribute slots every kit mesh uses; core-profile programs bind these names before linking.
enum AttributeSlot : GLuint { kVertexSlot = 0, kNormalSlot = 1, kTexCoord0Slot = 2 };

struct ProgramSpec {
    std::string name;                              // for messages: "gooch"
    std::vector<std::filesystem::path> files;      // one per stage; the stage comes from the extension
    std::vector<ShaderDefine> defines;
    std::vector<GeneratedFile> generated;          // in-memory include files, after the options' own
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

private:
    ProgramName name_;
    std::vector<std::filesystem::path> dependencies_;
    std::vector<std::string> compiled_sources_;
    mutable std::unordered_map<std::string, GLint> locations_;
};

}  // namespace gsv
