#pragma once
// Lab 06: the ray caster as a processor. Its compositing, gradient, classification and shading parameters
// pick the modules; the `shader` parameter picks how they are put together:
//   specialised: raycast.frag with a generated rc_config.glsl holding only the chosen modules (the lesson),
//   uber:        raycast_uber.frag, every module compiled in and chosen per draw by uniforms,
//   handwritten: raycast_dvr_handwritten.frag, one configuration written out by hand.
// The last two exist to measure what the first saves and costs.
#include "lab_processor.h"

#include "common/gl/gpu_mesh.h"
#include "common/gl/texture.h"
#include "common/params/change_tracker.h"
#include "common/shader/shader_library.h"
#include "raycast_modules.h"
#include "support/raycast/raycast_components.h"
#include "transfer_function.h"

#include <string>

namespace lab06 {

enum class Shader { Specialised, Uber, Handwritten };
inline constexpr gsv::EnumName<Shader> kShaders[] = {
    {Shader::Specialised, "specialised"}, {Shader::Uber, "uber"}, {Shader::Handwritten, "handwritten"}};

class RayTraversal final : public LabProcessor {
public:
    RayTraversal();
    void process() override;

    // The configuration the parameters ask for (before effective_config drops what the compositing cannot use).
    gsv::RaycastConfig config() const;
    // The program the last process() drew with: the specialised one's generated source can be read from it.
    const gsv::ShaderLibrary::Entry* last_program() const { return last_; }
    // The target of the last process(), kept when a later one fails.
    const std::shared_ptr<ImageData>& image() const { return image_; }
    // The transfer function's table as the classification module reads it (the legend samples it there too).
    const gsv::Texture& transfer_function();
    std::string transfer_function_name() const { return transfer_function_.param().get(); }
    const gsv::EnumParam<Shader>& shader() const { return shader_; }
    // What a frame of width x height asks at most (issue 44): each pixel's ray through the volume's box, from the
    // last frame's camera, sampled as raycast_skeleton.glsl steps it, each sample with the lookups its modules make
    // (early termination, transparent samples, clipping planes and geometry only shorten it). None before the first
    // frame has read the volume.
    gsv::FrameWork frame_work(int width, int height) const;
    double iso_value() const { return iso_.iso_value().in_double().get(); }

private:
    const gsv::ShaderLibrary::Entry& program_for(Shader shader, const gsv::RaycastConfig& config);

    const gsv::ShaderLibrary::Entry* specialised_ = nullptr;
    gsv::RaycastConfig specialised_config_;
    const gsv::ShaderLibrary::Entry* uber_ = nullptr;
    const gsv::ShaderLibrary::Entry* handwritten_ = nullptr;
    const gsv::ShaderLibrary::Entry* last_ = nullptr;
    // In the order of the parameters (the lab's list, the panel): the module choices, then what each module's
    // component declares and sets (support/raycast/raycast_components.h).
    gsv::Param<std::string> compositing_, gradient_, classification_, shading_;
    gsv::EnumParam<Shader> shader_;
    gsv::EnumParam<TransferFunction> transfer_function_;
    gsv::RaySetup rays_;
    FrameView last_view_;                       // the last frame's camera and volume box, for frame_work
    gsv::VolumeBox last_box_{glm::dvec3(1.0)};
    gsv::DvrCompositing dvr_;
    gsv::IsoCompositing iso_;
    gsv::PhongShading phong_;
    gsv::VoxelGeometry voxels_;
    gsv::GradientLookup gradients_;
    gsv::TransferFunctionLookup table_;
    gsv::UberModes modes_;
    gsv::GpuMesh quad_;
    gsv::Tracked<gsv::Texture> transfer_function_table_;
    std::shared_ptr<ImageData> image_;
};

}  // namespace lab06
