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
    add_property("compositing", "dvr", {"dvr", "mip", "iso", "fhp"});
    add_property("gradient", "central", {"none", "forward", "central", "precomputed"});
    add_property("classification", "tf", {"raw", "tf"});
    add_property("shading", "phong", {"none", "phong"});
    add_property("shader", "specialised", {"specialised", "uber", "handwritten"});
    add_property("transfer_function", "bands", kTransferFunctions);
    add_property("samples_per_voxel", "1");
    add_property("opacity_correction", "on");
    add_property("early_ray_threshold", "0.95");
    add_property("iso_value", "0.5");
    add_property("ambient", "0.25");
    add_property("diffuse", "0.7");
    add_property("specular", "0.3");
    add_property("shininess", "24");
}

Config RayTraversal::config() const {
    Config c;
    c.compositing = gsv::parse_compositing(property("compositing"));
    c.gradient = gsv::parse_gradient(property("gradient"));
    c.classification = gsv::parse_classification(property("classification"));
    c.shading = gsv::parse_shading(property("shading"));
    c.early_termination = number("early_ray_threshold", 0, 1) < 1.0;
    return c;
}

const gsv::ShaderLibrary::Entry& RayTraversal::program_for(const std::string& shader, const Config& config) {
    gsv::LabKit& k = kit();
    // Programs are named after this processor, so a compile error names who owns the shader.
    if (shader == "uber") {
        if (!uber_) uber_ = &k.program(describe() + " uber", {"gsv/fullscreen.vert", "raycast_uber.frag"});
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
        specialised_ = &k.shaders().add(std::move(spec), k.params().defines());
        specialised_config_ = config;
    } else if (config != specialised_config_) {
        specialised_config_ = config;
        if (auto error = k.shaders().set_generated(*specialised_, {gsv::raycast_config_file(config)}, k.params().defines()))
            throw gsv::Error(*error);
    }
    return *specialised_;
}

const gsv::Texture& RayTraversal::transfer_function() {
    const std::string& name = property("transfer_function");
    if (name != transfer_function_name_ || !transfer_function_.id()) {
        const std::vector<float> table = transfer_function_table(name);
        transfer_function_ = gsv::Texture::create_2d(kTransferFunctionEntries, 1, gsv::TexelFormat::RGBA32F, table.data());
        transfer_function_name_ = name;
    }
    return transfer_function_;
}

void RayTraversal::process() {
    auto volume = input<VolumeData>("volume");
    auto entry = input<ImageData>("entry");
    auto exit = input<ImageData>("exit");
    const Config requested = config();
    gsv::validate(requested);
    const gsv::ShaderLibrary::Entry& program_entry = program_for(property("shader"), requested);
    // A hot reload that broke the shader leaves the last good program running; the error belongs here.
    if (!program_entry.error().empty()) throw gsv::Error(program_entry.error());
    last_ = &program_entry;
    const gsv::ShaderProgram& program = program_entry.program();

    const FrameView& v = view();
    const gsv::Volume& vol = volume->volume;
    const int largest = std::max({vol.nx, vol.ny, vol.nz});
    const double samples_per_voxel = number("samples_per_voxel", 1.0 / 64, 64);
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
    phong.ambient = static_cast<float>(number("ambient", 0, 1));
    phong.diffuse = static_cast<float>(number("diffuse", 0, 1));
    phong.specular = static_cast<float>(number("specular", 0, 1));
    phong.shininess = static_cast<float>(number("shininess", 1, 256));
    gsv::DvrCompositing dvr;
    // Opacity correction off: a reference of 0 keeps every sample's opacity as the transfer function gives it.
    dvr.reference_step_size = flag("opacity_correction") ? voxel : 0.0f;
    dvr.early_ray_threshold = static_cast<float>(number("early_ray_threshold", 0, 1));
    gsv::IsoCompositing iso;
    iso.iso_value = static_cast<float>(number("iso_value", 0, 1));
    gsv::UberModes modes;
    modes.config = requested;
    gsv::ShaderComponents components{&rays, &voxels, &gradients, &classification, &phong, &dvr, &iso};
    if (property("shader") == "uber") components.push_back(&modes);
    gsv::apply_components(program, components);
    if (!quad_.vertex_count()) quad_ = gsv::GpuMesh(gsv::make_fullscreen_quad(), kit().profile());
    quad_.draw();
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    set_output("image", image_);
}

}  // namespace lab06
