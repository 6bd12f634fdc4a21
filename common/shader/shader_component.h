#pragma once
// The C++ half of a GLSL module, after Inviwo's shader components: the module's file declares its uniforms and
// samplers, and its component, alone, sets them. A program is fed by the components of the modules it was built
// from, each owning its own names, rather than by one long list of strings in whoever draws it.
#include "common/shader/shader_program.h"

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

using ShaderComponents = std::vector<const ShaderComponent*>;

void apply_components(const ShaderProgram& program, const ShaderComponents& components);

// What a test checks for every program a lab builds: each active uniform has exactly one owner. Returns one line
// per uniform that no component sets (it would keep its default silently) or that two claim; empty when none.
std::vector<std::string> uniform_ownership_problems(const ShaderProgram& program, const ShaderComponents& components);

}  // namespace gsv
