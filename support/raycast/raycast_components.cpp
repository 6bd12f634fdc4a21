#include "support/raycast/raycast_components.h"

namespace gsv {

std::vector<std::string> UberModes::uniforms() const {
    std::vector<std::string> names;
    for (const auto& [uniform, value] : raycast_uber_uniforms(RaycastConfig{})) names.push_back(uniform);
    return names;
}

void UberModes::apply(const ShaderProgram& program) const {
    for (const auto& [uniform, value] : raycast_uber_uniforms(config)) program.set(uniform, value);
}

}  // namespace gsv
