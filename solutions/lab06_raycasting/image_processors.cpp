#include "image_processors.h"

#include "common/gl/gl.h"
#include "common/scene/transforms.h"

namespace lab06 {

GeometryRenderer::GeometryRenderer() : LabProcessor("GeometryRenderer") {
    add_input("geometry", gsv::PortType::Geometry);
    add_output("image", gsv::PortType::Image);
    add_property("geometry_color", "0.95,0.55,0.15");
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
    program.set("uGeometryColor", vec3("geometry_color"));
    geometry->draw();
    glDisable(GL_DEPTH_TEST);
    set_output("image", image_);
}

Canvas::Canvas() : LabProcessor("Canvas") {
    add_input("image", gsv::PortType::Image);
    add_optional_input("geometry", gsv::PortType::Image);
    add_output("image", gsv::PortType::Image);
    add_property("background", "0.08,0.09,0.12");
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
    program.set("uBackground", vec3("background"));
    quad_.draw();
    set_output("image", image_);
}

}  // namespace lab06
