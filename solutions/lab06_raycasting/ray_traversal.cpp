#include "ray_traversal.h"

#include "common/core/error.h"
#include "common/core/number_text.h"
#include "common/gl/gl.h"
#include "support/geometry/ray_box.h"
#include "transfer_function.h"

#include <algorithm>
#include <cmath>

namespace lab06 {

using Config = gsv::RaycastConfig;

RayTraversal::RayTraversal()
    : LabProcessor("RayTraversal"),
      // The module choices are the module tables' rows (raycast_modules.cpp).
      compositing_(params().add_choice("compositing", "dvr", gsv::compositing_names(raycast_modules()),
                                       gsv::compositing_help(raycast_modules()))),
      gradient_(params().add_choice("gradient", "central", gsv::gradient_names(raycast_modules()), "how normals are estimated")),
      classification_(params().add_choice("classification", "tf", gsv::classification_names(raycast_modules()),
                                          "intensity as opacity, or the transfer function")),
      shading_(params().add_choice("shading", "phong", gsv::shading_names(raycast_modules()), "Phong needs a gradient")),
      shader_(params().add_enum("shader", Shader::Specialised, kShaders,
                                "only the chosen modules compiled; all of them chosen by uniforms; DVR written by hand")
                  .may_draw_the_same("each draws the specialised shader's picture (the hand-written one DVR only), at its own cost")),
      // Only the lab reads it: it makes the table the sampler uTransferFunction reads.
      transfer_function_(params().add_enum("transfer_function", TransferFunction::Bands, kTransferFunctions, "the 1D transfer function")
                             .without_uniform()),
      rays_(params()),
      dvr_(params()),
      iso_(params()),
      phong_(params()),
      modes_(raycast_modules()) {
    add_input("volume", gsv::PortType::Volume);
    add_input("entry", gsv::PortType::Image);
    add_input("exit", gsv::PortType::Image);
    add_output("image", gsv::PortType::Image);
    gsv::Param<float>(iso_.iso_value()).applies_when(compositing_.name(), {"iso"});
}

Config RayTraversal::config() const {
    Config c;
    const gsv::RaycastModules& modules = raycast_modules();
    c.compositing = gsv::parse_compositing(modules, compositing_.get());
    c.gradient = gsv::parse_gradient(modules, gradient_.get());
    c.classification = gsv::parse_classification(modules, classification_.get());
    c.shading = gsv::parse_shading(modules, shading_.get());
    c.early_termination = dvr_.early_ray_threshold().get() < 1.0f;
    return c;
}

const gsv::ShaderLibrary::Entry& RayTraversal::program_for(Shader shader, const Config& config) {
    gsv::LabKit& k = kit();
    // Programs are named after this processor, so a compile error names who owns the shader.
    if (shader == Shader::Uber) {
        if (!uber_) {
            gsv::ProgramSpec spec;
            spec.name = describe() + " uber";
            spec.files = {k.assets().shader_file("gsv/fullscreen.vert"), k.assets().shader_file("raycast_uber.frag")};
            spec.generated = {gsv::raycast_uber_file(raycast_modules())};
            uber_ = &k.shaders().add(std::move(spec), k.defines());
        }
        return *uber_;
    }
    if (shader == Shader::Handwritten) {
        Config wanted;
        wanted.compositing = Config::Compositing::Dvr;
        wanted.gradient = Config::Gradient::Central;
        wanted.classification = Config::Classification::TransferFunction;
        wanted.shading = Config::Shading::Phong;
        wanted.early_termination = config.early_termination;
        if (gsv::effective_config(raycast_modules(), config) != wanted)
            throw gsv::Error(name() + ".shader = 'handwritten' draws only " + gsv::describe(raycast_modules(), wanted) +
                             "; asked for " + gsv::describe(raycast_modules(), config));
        if (!handwritten_)
            handwritten_ = &k.program(describe() + " handwritten", {"gsv/fullscreen.vert", "raycast_dvr_handwritten.frag"});
        return *handwritten_;
    }
    if (!specialised_) {
        gsv::ProgramSpec spec;
        spec.name = describe();
        spec.files = {k.assets().shader_file("gsv/fullscreen.vert"), k.assets().shader_file("raycast.frag")};
        spec.generated = {gsv::raycast_config_file(raycast_modules(), config)};
        specialised_ = &k.shaders().add(std::move(spec), k.defines());
        specialised_config_ = config;
    } else if (config != specialised_config_) {
        specialised_config_ = config;
        if (auto error = k.shaders().set_generated(*specialised_, {gsv::raycast_config_file(raycast_modules(), config)}, k.defines()))
            throw gsv::Error(*error);
    }
    return *specialised_;
}

const gsv::Texture& RayTraversal::transfer_function() {
    transfer_function_table_.update(params(), [&] {
        const std::vector<float> table = transfer_function_table(transfer_function_.get());
        return gsv::Texture::create_2d(kTransferFunctionEntries, 1, gsv::TexelFormat::RGBA32F, table.data());
    });
    return *transfer_function_table_;
}

gsv::FrameWork RayTraversal::frame_work(int width, int height) const {
    if (!last_) return {};
    const Config c = config();
    // raycast_skeleton.glsl: ceil(length / step) samples, step = 1 / (samples_per_voxel x the largest side), at
    // most kRcMaxSamples (raycast_common.glsl); the longest ray through the texture cube is its diagonal.
    constexpr double kMaxSamples = 16384;
    const double step = static_cast<double>(rays_.step_size());
    // Each pixel's ray, from the near plane to the far plane, in texture space; its length inside [0,1]^3.
    const glm::dmat4 to_model = glm::inverse(glm::dmat4(last_view_.projection) * glm::dmat4(last_view_.view));
    auto texture_point = [&](double x, double y, double z) {
        const glm::dvec4 p = to_model * glm::dvec4(x, y, z, 1.0);
        return last_box_.texture_from_model(glm::dvec3(p) / p.w);
    };
    double rays = 0, samples = 0;
    for (int py = 0; py < height; ++py)
        for (int px = 0; px < width; ++px) {
            const double x = 2.0 * (px + 0.5) / width - 1.0, y = 2.0 * (py + 0.5) / height - 1.0;
            const glm::dvec3 near = texture_point(x, y, -1.0), far = texture_point(x, y, 1.0);
            const auto span = gsv::ray_box_span(near, far - near, glm::dvec3(0.0), glm::dvec3(1.0));
            if (!span) continue;
            const double length = (std::min(span->exit, 1.0) - std::max(span->entry, 0.0)) * glm::length(far - near);
            if (!(length >= 1e-6)) continue;
            rays += 1;
            samples += std::max(1.0, std::ceil(std::min(length / step, kMaxSamples) - 1e-3));
        }
    const double per_ray = rays > 0 ? samples / rays : 0;
    const bool dvr = c.compositing == Config::Compositing::Dvr;
    const bool per_sample_classify = c.classification == Config::Classification::TransferFunction &&
                                     (dvr || c.compositing == Config::Compositing::FirstHit);
    const bool per_sample_gradient = dvr && c.shading == Config::Shading::Phong;
    const bool hit_gradient = c.compositing == Config::Compositing::Isosurface && c.shading == Config::Shading::Phong;
    const double gradient_lookups = c.gradient == Config::Gradient::Central ? 6 : c.gradient == Config::Gradient::Forward ? 4 : 0;
    const std::string along = gsv::format_number(per_ray, 4) + " samples a ray on average over " +
                              gsv::format_number(rays, 6) + " rays";
    gsv::FrameWork work;
    work.upper_bound = true;
    const double volume_per_sample = 1 + (per_sample_gradient ? gradient_lookups : 0);
    work.items.push_back({gsv::WorkKind::Fetch, gsv::ShaderPath::Fragment, "R32F 3D",
                          samples * volume_per_sample + (hit_gradient ? rays * gradient_lookups : 0),
                          gsv::format_number(volume_per_sample, 3) + " volume lookups a sample, " + along});
    if (c.gradient == Config::Gradient::Precomputed && (per_sample_gradient || hit_gradient))
        work.items.push_back({gsv::WorkKind::Fetch, gsv::ShaderPath::Fragment, "RGB32F 3D", per_sample_gradient ? samples : rays,
                              "the precomputed gradient, once a " + std::string(per_sample_gradient ? "sample" : "ray")});
    if (per_sample_classify)
        work.items.push_back({gsv::WorkKind::Fetch, gsv::ShaderPath::Fragment, "RGBA32F 2D", samples,
                              "the transfer function, once a sample"});
    return work;
}

void RayTraversal::process() {
    auto volume = input<VolumeData>("volume");
    auto entry = input<ImageData>("entry");
    auto exit = input<ImageData>("exit");
    const Config requested = config();
    gsv::validate(raycast_modules(), requested);
    const gsv::ShaderLibrary::Entry& program_entry = program_for(shader_.get(), requested);
    // A hot reload that broke the shader leaves the last good program running; the error belongs here.
    if (!program_entry.error().empty()) throw gsv::Error(program_entry.error());
    last_ = &program_entry;
    const gsv::ShaderProgram& program = program_entry.program();

    const FrameView& v = view();
    const gsv::Volume& vol = volume->volume;
    const int largest = std::max({vol.nx, vol.ny, vol.nz});

    fit(image_, v);
    image_->bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);  // every pixel writes its hit's depth (gl_FragDepth)
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    program.use();
    // Each module's component sets what the module's file declares, its parameters' values among them; the program
    // gave every sampler its own unit. What the frame brings is set here.
    rays_.entry_points = &entry->color();
    rays_.exit_points = &exit->color();
    rays_.volume = &volume->texture;
    rays_.largest_side = largest;
    last_view_ = v;
    last_view_.kit = nullptr;
    last_box_ = volume->box;
    rays_.texture_to_clip = v.projection * v.view * volume->box.model_from_texture_matrix();
    voxels_.spacing = glm::vec3(vol.spacing);
    gradients_.gradients = requested.gradient == Config::Gradient::Precomputed ? &volume->gradients() : &volume->texture;
    table_.table = &transfer_function();
    phong_.camera_position = glm::vec3(volume->box.texture_from_model(glm::dvec3(v.eye)));
    phong_.light_position = phong_.camera_position;  // a headlight
    dvr_.voxel_step = 1.0f / static_cast<float>(largest);
    modes_.config = requested;
    gsv::ShaderComponents components{&rays_, &voxels_, &gradients_, &table_, &phong_, &dvr_, &iso_};
    if (shader_.get() == Shader::Uber) components.push_back(&modes_);
    gsv::apply_components(program, components);
    if (!quad_.vertex_count()) quad_ = gsv::GpuMesh(gsv::make_fullscreen_quad(), kit().profile());
    quad_.draw();
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    set_output("image", image_);
}

}  // namespace lab06
