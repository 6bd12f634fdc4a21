#pragma once
// The C++ half of each of the ray caster's GLSL modules (common/shader/shader_component.h): each declares the
// parameters it reads, into the ray caster's (a processor's) parameters, and names each uniform once, beside the
// parameter or member it is set from. Every uniform the skeleton and the modules declare has one component that sets
// it, and a program gets the components of what it was built from. The uber-shader and the hand-written DVR declare
// the same names, so the same components feed them; UberModes adds the uber-shader's mode switches.
#include "common/gl/texture.h"
#include "common/params/params.h"
#include "common/shader/shader_component.h"
#include "support/raycast/raycast_config.h"

#include <glm/glm.hpp>

namespace gsv {

// The skeleton's: the rays, the volume they sample and the step between samples (samples_per_voxel).
class RaySetup final : public BoundShaderComponent {
public:
    explicit RaySetup(Params& params);
    std::string name() const override { return "ray setup (the skeleton)"; }
    float step_size() const;  // texture units between samples: 1 / (samples per voxel x the largest side)

    const Texture* entry_points = nullptr;  // front faces' texture coordinates
    const Texture* exit_points = nullptr;   // back faces'
    const Texture* volume = nullptr;
    int largest_side = 1;  // voxels along the volume's largest side
    glm::mat4 texture_to_clip{1.0f};
    glm::vec4 background{0.0f};  // premultiplied, where no ray hits

private:
    Param<double> samples_per_voxel_;
};

// The volume's geometry: a voxel's size, so differences are per unit of length.
class VoxelGeometry final : public BoundShaderComponent {
public:
    VoxelGeometry() { bind("uVoxelSpacing", spacing); }
    std::string name() const override { return "voxel geometry"; }
    glm::vec3 spacing{1.0f};
};

// The precomputed gradient's: the gradient volume. The uber-shader declares it whatever it computes, so it gets a
// 3D texture either way (a sampler3D with nothing bound on its unit would fail the draw).
class GradientLookup final : public BoundShaderComponent {
public:
    GradientLookup() { bind_texture("uGradientVolume", gradients); }
    std::string name() const override { return "gradient lookup"; }
    const Texture* gradients = nullptr;
};

// The transfer function classification's: the table, 1D in a texture of height 1.
class TransferFunctionLookup final : public BoundShaderComponent {
public:
    TransferFunctionLookup() { bind_texture("uTransferFunction", table); }
    std::string name() const override { return "transfer function"; }
    const Texture* table = nullptr;
};

// Phong shading's: a light and the camera in volume texture coordinates, and the coefficients (ambient, diffuse,
// specular, shininess).
class PhongShading final : public BoundShaderComponent {
public:
    explicit PhongShading(Params& params);
    std::string name() const override { return "Phong shading"; }
    glm::vec3 light_position{0.0f}, camera_position{0.0f};
};

// DVR compositing's: opacity correction (opacity_correction; a reference step of 0 turns it off) and early ray
// termination (early_ray_threshold).
class DvrCompositing final : public BoundShaderComponent {
public:
    explicit DvrCompositing(Params& params);
    std::string name() const override { return "DVR compositing"; }
    const Param<float>& early_ray_threshold() const { return early_ray_threshold_; }
    float voxel_step = 0;  // the step a transfer function's opacities are for: a voxel of the largest side

private:
    Param<bool> opacity_correction_;
    Param<float> early_ray_threshold_;
};

// Isosurface compositing's: the value whose surface is drawn (iso_value).
class IsoCompositing final : public BoundShaderComponent {
public:
    explicit IsoCompositing(Params& params);
    std::string name() const override { return "isosurface compositing"; }
    const Param<float>& iso_value() const { return iso_value_; }

private:
    Param<float> iso_value_;
};

// The uber-shader's: the modes a specialised shader would have compiled in (raycast_uber_uniforms).
class UberModes final : public ShaderComponent {
public:
    explicit UberModes(const RaycastModules& modules) : modules_(modules) {}
    std::string name() const override { return "uber-shader modes"; }
    std::vector<std::string> uniforms() const override;
    void apply(const ShaderProgram& program) const override;
    RaycastConfig config;

private:
    const RaycastModules& modules_;
};

}  // namespace gsv
