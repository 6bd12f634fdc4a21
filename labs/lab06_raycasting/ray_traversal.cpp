#include "ray_traversal.h"

#include "common/core/error.h"
#include "common/gl/gl.h"
#include "transfer_function.h"

#include <algorithm>

namespace lab06 {

using Config = gsv::RaycastConfig;

RayTraversal::RayTraversal() : LabProcessor("RayTraversal") {
    add_input("volume", gsv::PortType::Volume);
    add_input("entry", gsv::PortType::Image);
    add_input("exit", gsv::PortType::Image);
    add_output("image", gsv::PortType::Image);
    gsv::Params& p = params();
    // The module choices are the module tables' names (support/raycast/raycast_config.h).
    compositing_ = p.add_choice("compositing", "dvr", gsv::compositing_names(),
                                "direct volume rendering, maximum intensity, isosurface, first hit");
    gradient_ = p.add_choice("gradient", "central", gsv::gradient_names(), "how normals are estimated");
    classification_ = p.add_choice("classification", "tf", gsv::classification_names(),
                                   "intensity as opacity, or the transfer function");
    shading_ = p.add_choice("shading", "phong", gsv::shading_names(), "Phong needs a gradient");
    shader_ = p.add_choice("shader", "specialised", {"specialised", "uber", "handwritten"},
                           "only the chosen modules compiled; all of them chosen by uniforms; DVR written by hand");
    transfer_function_name_ = p.add_choice("transfer_function", "bands", kTransferFunctions, "the 1D transfer function");
    // [0.05, 32]: the sweep's reference refines to 32, and below 0.05 a ray of a 41-voxel volume takes two samples.
    samples_per_voxel_ = p.add_float("samples_per_voxel", 1, 0.05, 32, "samples along a ray per voxel (of the largest side)")
                             .with_step(0.25)
                             .in_double();
    opacity_correction_ = p.add_bool("opacity_correction", true,
                                     "alpha' = 1 - (1 - alpha)^(step / voxel): the image keeps its opacity as the step changes");
    early_ray_threshold_ = p.add_float("early_ray_threshold", 0.95, 0, 1, "DVR stops a ray once it is this opaque (1: never)").with_step(0.01);
    iso_value_ = p.add_float("iso_value", 0.5, 0, 1, "the isosurface's value").with_step(0.01).applies_when("compositing", {"iso"});
    ambient_ = p.add_float("ambient", 0.25, 0, 1, "Phong k_a");
    diffuse_ = p.add_float("diffuse", 0.7, 0, 1, "Phong k_d");
    specular_ = p.add_float("specular", 0.3, 0, 1, "Phong k_s");
    shininess_ = p.add_float("shininess", 24, 1, 256, "Phong exponent").with_step(4);
}

Config RayTraversal::config() const {
    Config c;
    c.compositing = gsv::parse_compositing(compositing_.get());
    c.gradient = gsv::parse_gradient(gradient_.get());
    c.classification = gsv::parse_classification(classification_.get());
    c.shading = gsv::parse_shading(shading_.get());
    c.early_termination = early_ray_threshold_.get() < 1.0f;
    return c;
}

const gsv::ShaderLibrary::Entry& RayTraversal::program_for(const std::string& shader, const Config& config) {
    gsv::LabKit& k = kit();
    // Programs are named after this processor, so a compile error names who owns the shader.
    if (shader == "uber") {
        if (!uber_) {
            gsv::ProgramSpec spec;
            spec.name = describe() + " uber";
            spec.files = {k.assets().shader_file("gsv/fullscreen.vert"), k.assets().shader_file("raycast_uber.frag")};
            spec.generated = {gsv::raycast_uber_file()};
            uber_ = &k.shaders().add(std::move(spec), k.defines());
        }
        return *uber_;
    }
    if (shader == "handwritten") {
        Config wanted;
        wanted.compositing = Config::Compositing::Dvr;
        wanted.gradient = Config::Gradient::Central;
        wanted.classification = Config::Classification::TransferFunction;
        wanted.shading = Config::Shading::Phong;
        wanted.early_termination = config.early_termination;
        if (gsv::effective_config(config) != wanted)
            throw gsv::Error(name() + ".shader = 'handwritten' draws only " + gsv::describe(wanted) + "; asked for " +
                             gsv::describe(config));
        if (!handwritten_)
            handwritten_ = &k.program(describe() + " handwritten", {"gsv/fullscreen.vert", "raycast_dvr_handwritten.frag"});
        return *handwritten_;
    }
    if (!specialised_) {
        gsv::ProgramSpec spec;
        spec.name = describe();
        spec.files = {k.assets().shader_file("gsv/fullscreen.vert"), k.assets().shader_file("raycast.frag")};
        spec.generated = {gsv::raycast_config_file(config)};
        specialised_ = &k.shaders().add(std::move(spec), k.defines());
        specialised_config_ = config;
    } else if (config != specialised_config_) {
        specialised_config_ = config;
        if (auto error = k.shaders().set_generated(*specialised_, {gsv::raycast_config_file(config)}, k.defines()))
            throw gsv::Error(*error);
    }
    return *specialised_;
}

const gsv::Texture& RayTraversal::transfer_function() {
    transfer_function_.update(params(), [&] {
        const std::vector<float> table = transfer_function_table(transfer_function_name_.get());
        return gsv::Texture::create_2d(kTransferFunctionEntries, 1, gsv::TexelFormat::RGBA32F, table.data());
    });
    return *transfer_function_;
}

void RayTraversal::process() {
    auto volume = input<VolumeData>("volume");
    auto entry = input<ImageData>("entry");
    auto exit = input<ImageData>("exit");
    const Config requested = config();
    gsv::validate(requested);
    const gsv::ShaderLibrary::Entry& program_entry = program_for(shader_.get(), requested);
    // A hot reload that broke the shader leaves the last good program running; the error belongs here.
    if (!program_entry.error().empty()) throw gsv::Error(program_entry.error());
    last_ = &program_entry;
    const gsv::ShaderProgram& program = program_entry.program();

    const FrameView& v = view();
    const gsv::Volume& vol = volume->volume;
    const int largest = std::max({vol.nx, vol.ny, vol.nz});
    const double samples_per_voxel = samples_per_voxel_.get();
    const float voxel = 1.0f / static_cast<float>(largest);  // the step a transfer function's opacities are for
    const float step = static_cast<float>(1.0 / (samples_per_voxel * largest));

    fit(image_, v);
    image_->bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);  // every pixel writes its hit's depth (gl_FragDepth)
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    program.use();
    // Each module's component sets what the module's file declares; the program gave every sampler its own unit.
    gsv::RaySetup rays(entry->color(), exit->color(), volume->texture);
    rays.step_size = step;
    rays.texture_to_clip = v.projection * v.view * volume->box.model_from_texture_matrix();
    gsv::VoxelGeometry voxels;
    voxels.spacing = glm::vec3(vol.spacing);
    const gsv::GradientLookup gradients(requested.gradient == Config::Gradient::Precomputed ? volume->gradients()
                                                                                            : volume->texture);
    const gsv::TransferFunctionLookup classification(transfer_function());
    gsv::PhongShading phong;
    phong.camera_position = glm::vec3(volume->box.texture_from_model(glm::dvec3(v.eye)));
    phong.light_position = phong.camera_position;  // a headlight
    phong.ambient = ambient_.get();
    phong.diffuse = diffuse_.get();
    phong.specular = specular_.get();
    phong.shininess = shininess_.get();
    gsv::DvrCompositing dvr;
    // Opacity correction off: a reference of 0 keeps every sample's opacity as the transfer function gives it.
    dvr.reference_step_size = opacity_correction_.get() ? voxel : 0.0f;
    dvr.early_ray_threshold = early_ray_threshold_.get();
    gsv::IsoCompositing iso;
    iso.iso_value = iso_value_.get();
    gsv::UberModes modes;
    modes.config = requested;
    gsv::ShaderComponents components{&rays, &voxels, &gradients, &classification, &phong, &dvr, &iso};
    if (shader_.get() == "uber") components.push_back(&modes);
    gsv::apply_components(program, components);
    if (!quad_.vertex_count()) quad_ = gsv::GpuMesh(gsv::make_fullscreen_quad(), kit().profile());
    quad_.draw();
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    set_output("image", image_);
}

}  // namespace lab06
