#pragma once
// The C++ half of a GLSL module, after Inviwo's shader components: the module's file declares its uniforms and
// samplers, and its component, alone, sets them. A program is fed by the components of the modules it was built
// from, each owning its own names, rather than by one long list of strings in whoever draws it.
#include "common/shader/shader_program.h"

#include <functional>
#include <string>
#include <vector>

namespace gsv {

class ShaderComponent {
public:
    virtual ~ShaderComponent() = default;
    // For messages: what the module does and the GLSL file it feeds.
    virtual std::string name() const = 0;
    // The uniforms, samplers included, that its GLSL declares.
    virtual std::vector<std::string> uniforms() const = 0;
    // Sets them on `program`, which is in use; textures through program.bind, on the units the program gave out.
    // A uniform the program does not have (a module left out, or dropped as unused) is skipped.
    virtual void apply(const ShaderProgram& program) const = 0;
};

// A component that names each uniform once, beside what it is set from: uniforms() and apply() both read the list.
//     std::vector<Binding> bindings() const override { return {texture("uVolume", volume), value("uStepSize", step_size)}; }
class BoundShaderComponent : public ShaderComponent {
public:
    std::vector<std::string> uniforms() const final;
    void apply(const ShaderProgram& program) const final;

protected:
    struct Binding {
        std::string uniform;
        std::function<void(const ShaderProgram&, const std::string&)> set;
    };
    // The list; the values are read when apply() runs, so it holds references to the component's members.
    virtual std::vector<Binding> bindings() const = 0;
    template <class T>
    static Binding value(std::string uniform, const T& member) {
        return {std::move(uniform), [&member](const ShaderProgram& program, const std::string& name) { program.set(name, member); }};
    }
    template <class TextureType>
    static Binding texture(std::string uniform, const TextureType& member) {
        return {std::move(uniform), [&member](const ShaderProgram& program, const std::string& name) { program.bind(name, member); }};
    }
};

using ShaderComponents = std::vector<const ShaderComponent*>;

void apply_components(const ShaderProgram& program, const ShaderComponents& components);

// What a test checks for every program a lab builds: each active uniform has exactly one owner. Returns one line
// per uniform that no component sets (it would keep its default silently) or that two claim; empty when none.
std::vector<std::string> uniform_ownership_problems(const ShaderProgram& program, const ShaderComponents& components);

}  // namespace gsv
