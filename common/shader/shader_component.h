#pragma once
// The C++ half of a GLSL module, after Inviwo's shader components: the module's file declares its uniforms and
// samplers, and its component, alone, sets them. A program is fed by the components of the modules it was built
// from, each owning its own names, rather than by one long list of strings in whoever draws it.
#include "common/params/params.h"
#include "common/shader/shader_program.h"

#include <functional>
#include <string>
#include <type_traits>
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

// A component that names each uniform once, in one list its constructor makes, beside what the uniform is set from:
// a parameter the component declares (it owns it, as an Inviwo component owns its properties; the processor's
// parameters hold it, so the command line, case files, network files, the panel and sweeps reach it as any other), a
// member the drawing code sets, a texture, or a value made from those when apply() runs.
//     explicit PhongShading(Params& p) {
//         bind("uCameraPosition", camera_position);
//         bind_param("uAmbient", p.add_float("ambient", 0.25, 0, 1, "Phong k_a"));
//     }
class BoundShaderComponent : public ShaderComponent {
public:
    BoundShaderComponent(const BoundShaderComponent&) = delete;  // the list refers to this one's members
    BoundShaderComponent& operator=(const BoundShaderComponent&) = delete;
    std::vector<std::string> uniforms() const final;
    void apply(const ShaderProgram& program) const final;

protected:
    BoundShaderComponent() = default;
    // A member, read when apply() runs.
    template <class T>
    void bind(std::string uniform, const T& member) {
        add(std::move(uniform), [&member](const ShaderProgram& program, const std::string& name) { program.set(name, member); });
    }
    // A parameter, declared in the call: its spec names the uniform too (`list` says so), and the uniform takes its
    // value, typed (a float read in double as float). Returns it, for the component's own reads.
    template <class T>
    Param<T> bind_param(std::string uniform, Param<T> param) {
        static_assert(!std::is_same_v<T, std::string>, "a choice reaches GLSL as a define or a module, not a uniform");
        param.with_uniform(uniform);
        add(std::move(uniform), [param](const ShaderProgram& program, const std::string& name) {
            if constexpr (std::is_same_v<T, double>) program.set(name, static_cast<float>(param.get()));
            else program.set(name, param.get());
        });
        return param;
    }
    // A texture the drawing code points `member` at before apply(); none there is an error naming the uniform.
    template <class TextureType>
    void bind_texture(std::string uniform, const TextureType* const& member) {
        add(std::move(uniform), [this, &member](const ShaderProgram& program, const std::string& name) {
            if (!member) throw_no_texture(name);
            program.bind(name, *member);
        });
    }
    // A value made when apply() runs (a step from the samples per voxel and the volume's size).
    template <class F>
    void bind_computed(std::string uniform, F value) {
        add(std::move(uniform), [value](const ShaderProgram& program, const std::string& name) { program.set(name, value()); });
    }

private:
    using Setter = std::function<void(const ShaderProgram&, const std::string&)>;
    void add(std::string uniform, Setter set);
    [[noreturn]] void throw_no_texture(const std::string& uniform) const;
    struct Binding {
        std::string uniform;
        Setter set;
    };
    std::vector<Binding> bindings_;
};

using ShaderComponents = std::vector<const ShaderComponent*>;

void apply_components(const ShaderProgram& program, const ShaderComponents& components);

// What a test checks for every program a lab builds: each active uniform has exactly one owner. Returns one line
// per uniform that no component sets (it would keep its default silently) or that two claim; empty when none.
std::vector<std::string> uniform_ownership_problems(const ShaderProgram& program, const ShaderComponents& components);

}  // namespace gsv
