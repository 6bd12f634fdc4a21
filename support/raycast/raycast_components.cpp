#include "support/raycast/raycast_components.h"

namespace gsv {

RaySetup::RaySetup(Params& p) {
    bind_texture("uEntryPoints", entry_points);
    bind_texture("uExitPoints", exit_points);
    bind_texture("uVolume", volume);
    // [0.05, 32]: the sweep's reference refines to 32, and below 0.05 a ray of a 41-voxel volume takes two samples.
    // Read in double, as typed: the step is its reciprocal.
    samples_per_voxel_ = p.add_float("samples_per_voxel", 1, 0.05, 32, "samples along a ray per voxel (of the largest side)")
                             .with_step(0.25)
                             .in_double();
    bind_computed("uStepSize", [this] { return step_size(); });
    bind("uTextureToClip", texture_to_clip);
    bind("uBackground", background);
}

float RaySetup::step_size() const { return static_cast<float>(1.0 / (samples_per_voxel_.get() * largest_side)); }

PhongShading::PhongShading(Params& p) {
    bind("uLightPosition", light_position);
    bind("uCameraPosition", camera_position);
    bind_param("uAmbient", p.add_float("ambient", 0.25, 0, 1, "Phong k_a"));
    bind_param("uDiffuse", p.add_float("diffuse", 0.7, 0, 1, "Phong k_d"));
    bind_param("uSpecular", p.add_float("specular", 0.3, 0, 1, "Phong k_s"));
    bind_param("uShininess", p.add_float("shininess", 24, 1, 256, "Phong exponent").with_step(4));
}

DvrCompositing::DvrCompositing(Params& p) {
    opacity_correction_ = p.add_bool("opacity_correction", true,
                                     "alpha' = 1 - (1 - alpha)^(step / voxel): the image keeps its opacity as the step changes");
    // Opacity correction off: a reference of 0 keeps every sample's opacity as the transfer function gives it.
    bind_computed("uReferenceStepSize", [this] { return opacity_correction_.get() ? voxel_step : 0.0f; });
    early_ray_threshold_ = bind_param("uEarlyRayThreshold", p.add_float("early_ray_threshold", 0.95, 0, 1,
                                                                         "DVR stops a ray once it is this opaque (1: never)")
                                                                 .with_step(0.01));
}

IsoCompositing::IsoCompositing(Params& p) {
    iso_value_ = bind_param("uIsoValue", p.add_float("iso_value", 0.5, 0, 1, "the isosurface's value").with_step(0.01));
}

std::vector<std::string> UberModes::uniforms() const {
    std::vector<std::string> names;
    for (const auto& [uniform, value] : raycast_uber_uniforms(modules_, RaycastConfig{})) names.push_back(uniform);
    return names;
}

void UberModes::apply(const ShaderProgram& program) const {
    for (const auto& [uniform, value] : raycast_uber_uniforms(modules_, config)) program.set(uniform, value);
}

}  // namespace gsv
