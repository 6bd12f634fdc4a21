#include "support/raycast/raycast_components.h"

namespace gsv {

std::vector<std::string> RaySetup::uniforms() const {
    return {"uEntryPoints", "uExitPoints", "uVolume", "uStepSize", "uTextureToClip", "uBackground"};
}

void RaySetup::apply(const ShaderProgram& program) const {
    program.bind("uEntryPoints", entry_points);
    program.bind("uExitPoints", exit_points);
    program.bind("uVolume", volume);
    program.set("uStepSize", step_size);
    program.set("uTextureToClip", texture_to_clip);
    program.set("uBackground", background);
}

void VoxelGeometry::apply(const ShaderProgram& program) const { program.set("uVoxelSpacing", spacing); }

void GradientLookup::apply(const ShaderProgram& program) const { program.bind("uGradientVolume", gradients); }

void TransferFunctionLookup::apply(const ShaderProgram& program) const { program.bind("uTransferFunction", table); }

std::vector<std::string> PhongShading::uniforms() const {
    return {"uLightPosition", "uCameraPosition", "uAmbient", "uDiffuse", "uSpecular", "uShininess"};
}

void PhongShading::apply(const ShaderProgram& program) const {
    program.set("uLightPosition", light_position);
    program.set("uCameraPosition", camera_position);
    program.set("uAmbient", ambient);
    program.set("uDiffuse", diffuse);
    program.set("uSpecular", specular);
    program.set("uShininess", shininess);
}

void DvrCompositing::apply(const ShaderProgram& program) const {
    program.set("uReferenceStepSize", reference_step_size);
    program.set("uEarlyRayThreshold", early_ray_threshold);
}

void IsoCompositing::apply(const ShaderProgram& program) const { program.set("uIsoValue", iso_value); }

std::vector<std::string> UberModes::uniforms() const {
    std::vector<std::string> names;
    for (const auto& [uniform, value] : raycast_uber_uniforms(RaycastConfig{})) names.push_back(uniform);
    return names;
}

void UberModes::apply(const ShaderProgram& program) const {
    for (const auto& [uniform, value] : raycast_uber_uniforms(config)) program.set(uniform, value);
}

}  // namespace gsv
