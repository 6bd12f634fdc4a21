#pragma once
// The C++ half of each of the ray caster's GLSL modules (common/shader/shader_component.h), each uniform named
// once beside the member it is set from: every uniform the
// skeleton and the modules declare has one component that sets it, and a program gets the components of what it
// was built from. The uber-shader and the hand-written DVR declare the same names, so the same components feed
// them; UberModes adds the uber-shader's mode switches.
#include "common/gl/texture.h"
#include "common/shader/shader_component.h"
#include "support/raycast/raycast_config.h"

#include <glm/glm.hpp>

namespace gsv {

// raycast_skeleton.glsl and raycast_common.glsl: the rays and the volume they sample.
struct RaySetup final : BoundShaderComponent {
    const Texture& entry_points;  // front faces' texture coordinates
    const Texture& exit_points;   // back faces'
    const Texture& volume;
    float step_size = 0;          // texture units between samples
    glm::mat4 texture_to_clip{1.0f};
    glm::vec4 background{0.0f};   // premultiplied, where no ray hits
    RaySetup(const Texture& entry, const Texture& exit, const Texture& vol) : entry_points(entry), exit_points(exit), volume(vol) {}
    std::string name() const override { return "ray setup (raycast_skeleton.glsl, raycast_common.glsl)"; }
    std::vector<Binding> bindings() const override {
        return {texture("uEntryPoints", entry_points), texture("uExitPoints", exit_points), texture("uVolume", volume),
                value("uStepSize", step_size),         value("uTextureToClip", texture_to_clip), value("uBackground", background)};
    }
};

// volume_geometry.glsl: a voxel's size, so differences are per unit of length.
struct VoxelGeometry final : BoundShaderComponent {
    glm::vec3 spacing{1.0f};
    std::string name() const override { return "voxel geometry (volume_geometry.glsl)"; }
    std::vector<Binding> bindings() const override { return {value("uVoxelSpacing", spacing)}; }
};

// gradient_precomputed.glsl: the gradient volume. The uber-shader declares it whatever it computes, so it gets a
// 3D texture either way (a sampler3D with nothing bound on its unit would fail the draw).
struct GradientLookup final : BoundShaderComponent {
    const Texture& gradients;
    explicit GradientLookup(const Texture& g) : gradients(g) {}
    std::string name() const override { return "gradient lookup (gradient_precomputed.glsl)"; }
    std::vector<Binding> bindings() const override { return {texture("uGradientVolume", gradients)}; }
};

// classify_tf.glsl: the transfer function, a 1D table in a texture of height 1.
struct TransferFunctionLookup final : BoundShaderComponent {
    const Texture& table;
    explicit TransferFunctionLookup(const Texture& t) : table(t) {}
    std::string name() const override { return "transfer function (classify_tf.glsl)"; }
    std::vector<Binding> bindings() const override { return {texture("uTransferFunction", table)}; }
};

// shade_phong.glsl: a light and the camera in volume texture coordinates, and the Phong coefficients.
struct PhongShading final : BoundShaderComponent {
    glm::vec3 light_position{0.0f}, camera_position{0.0f};
    float ambient = 0.25f, diffuse = 0.7f, specular = 0.3f, shininess = 24.0f;
    std::string name() const override { return "Phong shading (shade_phong.glsl)"; }
    std::vector<Binding> bindings() const override {
        return {value("uLightPosition", light_position), value("uCameraPosition", camera_position), value("uAmbient", ambient),
                value("uDiffuse", diffuse), value("uSpecular", specular), value("uShininess", shininess)};
    }
};

// composite_dvr.glsl: opacity correction (a reference step of 0 turns it off) and early ray termination.
struct DvrCompositing final : BoundShaderComponent {
    float reference_step_size = 0, early_ray_threshold = 1;
    std::string name() const override { return "DVR compositing (composite_dvr.glsl)"; }
    std::vector<Binding> bindings() const override {
        return {value("uReferenceStepSize", reference_step_size), value("uEarlyRayThreshold", early_ray_threshold)};
    }
};

// composite_iso.glsl: the value whose surface is drawn.
struct IsoCompositing final : BoundShaderComponent {
    float iso_value = 0.5f;
    std::string name() const override { return "isosurface compositing (composite_iso.glsl)"; }
    std::vector<Binding> bindings() const override { return {value("uIsoValue", iso_value)}; }
};

// raycast_uber.frag: the modes a specialised shader would have compiled in (raycast_uber_uniforms).
struct UberModes final : ShaderComponent {
    RaycastConfig config;
    std::string name() const override { return "uber-shader modes (raycast_uber.frag)"; }
    std::vector<std::string> uniforms() const override;
    void apply(const ShaderProgram& program) const override;
};

}  // namespace gsv
