#include "image_processors.h"

#include "common/gl/gl.h"
#include "common/scene/transforms.h"

namespace lab06 {

GeometryRenderer::GeometryRenderer() : LabProcessor("GeometryRenderer") {
    add_input("geometry", gsv::PortType::Geometry);
    add_output("image", gsv::PortType::Image);
    geometry_color_ = params()
                          .add_vec3("geometry_color", {0.95f, 0.55f, 0.15f}, 0, 1, "the opaque geometry's colour")
                          .may_draw_the_same("only a network with geometry in it draws it (the default network has none)");
}

void GeometryRenderer::process() {
    auto geometry = input<GeometryData>("geometry");
    const FrameView& v = view();
    if (!program_) program_ = &kit().program(describe(), {"geometry.vert", "geometry.frag"});
    const gsv::ShaderProgram& program = program_->program();
    fit(image_, v);
    image_->bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    program.use();
    set_transforms(program, geometry->box.model_from_texture_matrix());
    // The normals are in model space, not in the texture space the positions are in.
    program.set("uNormalMatrix", glm::mat3(v.view));
    program.set("uGeometryColor", geometry_color_.get());
    geometry->draw();
    glDisable(GL_DEPTH_TEST);
    set_output("image", image_);
}

Canvas::Canvas() : LabProcessor("Canvas") {
    add_input("image", gsv::PortType::Image);
    add_optional_input("geometry", gsv::PortType::Image);
    add_output("image", gsv::PortType::Image);
    // The canvas sets it on canvas.frag itself (process()); the ray caster's uBackground is another, a vec4 (RaySetup).
    background_ = params().add_vec3("background", {0.08f, 0.09f, 0.12f}, 0, 1, "the canvas behind everything").without_uniform();
}

void Canvas::process() {
    auto volume = input<ImageData>("image");
    auto geometry = input<ImageData>("geometry");
    const FrameView& v = view();
    if (!program_) program_ = &kit().program(describe(), {"gsv/fullscreen.vert", "canvas.frag"});
    if (!quad_.vertex_count()) quad_ = gsv::GpuMesh(gsv::make_fullscreen_quad(), kit().profile());
    const gsv::ShaderProgram& program = program_->program();
    fit(image_, v);
    image_->bind();
    glDisable(GL_DEPTH_TEST);
    glClearDepthf(1.0f);
    glClear(GL_DEPTH_BUFFER_BIT);  // a picture, not a scene: no depth
    program.use();
    program.bind("uImage", volume->color());
    program.bind("uGeometryImage", (geometry ? geometry : volume)->color());
    program.set("uHasGeometry", geometry != nullptr);
    program.set("uBackground", background_.get());
    quad_.draw();
    set_output("image", image_);
}

}  // namespace lab06
