#include "common/shader/shader_component.h"

#include "common/core/error.h"

#include <map>

namespace gsv {

std::vector<std::string> BoundShaderComponent::uniforms() const {
    std::vector<std::string> names;
    for (const Binding& binding : bindings_) names.push_back(binding.uniform);
    return names;
}

void BoundShaderComponent::apply(const ShaderProgram& program) const {
    for (const Binding& binding : bindings_) binding.set(program, binding.uniform);
}

void BoundShaderComponent::add(std::string uniform, Setter set) { bindings_.push_back({std::move(uniform), std::move(set)}); }

void BoundShaderComponent::throw_no_texture(const std::string& uniform) const {
    throw Error(name() + ": " + uniform + " has no texture to bind");
}

void apply_components(const ShaderProgram& program, const ShaderComponents& components) {
    for (const ShaderComponent* component : components) component->apply(program);
}

std::vector<std::string> uniform_ownership_problems(const ShaderProgram& program, const ShaderComponents& components) {
    std::map<std::string, std::vector<std::string>> owners;
    for (const ShaderComponent* component : components)
        for (const std::string& uniform : component->uniforms()) owners[uniform].push_back(component->name());
    std::vector<std::string> problems;
    for (std::string uniform : program.active_uniforms()) {
        if (uniform.size() > 3 && uniform.compare(uniform.size() - 3, 3, "[0]") == 0) uniform.resize(uniform.size() - 3);
        const auto it = owners.find(uniform);
        if (it == owners.end()) {
            problems.push_back(uniform + ": set by no component");
        } else if (it->second.size() > 1) {
            std::string who;
            for (const auto& name : it->second) who += (who.empty() ? "" : " and ") + name;
            problems.push_back(uniform + ": claimed by " + who);
        }
    }
    return problems;
}

}  // namespace gsv
