#include "entry_exit.h"

#include "common/gl/gl.h"
#include "common/scene/transforms.h"

namespace lab06 {

EntryExitPoints::EntryExitPoints() : LabProcessor("EntryExitPoints") {
    add_input("proxy", gsv::PortType::Geometry);
    add_optional_input("occluder", gsv::PortType::Geometry);
    add_output("entry", gsv::PortType::Image);
    add_output("exit", gsv::PortType::Image);
}

void EntryExitPoints::process() {
    auto proxy = input<GeometryData>("proxy");
    auto occluder = input<GeometryData>("occluder");
    const FrameView& v = view();
    if (!program_) program_ = &kit().program(name() + " (proxy)", {"proxy.vert", "proxy.frag"});
    const gsv::ShaderProgram& program = program_->program();
    program.use();
    set_transforms(program, proxy->box.model_from_texture_matrix());
    fit(entry_, v);
    fit(exit_, v);

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);

    // Exit points: the farthest back faces.
    exit_->bind();
    glClearDepthf(0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDepthFunc(GL_GREATER);
    glCullFace(GL_FRONT);
    proxy->draw();
    // The geometry's front faces, where they lie before the exit: the rays stop at them.
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);
    if (occluder) occluder->draw();

    // Entry points: the nearest front faces, and where the near plane cuts the proxy (the camera inside),
    // the cut itself, so those rays start at the near plane rather than not at all.
    entry_->bind();
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    proxy->draw();
    if (proxy->proxy) {
        const gsv::Plane near_model = gsv::near_plane(glm::dvec3(v.eye), glm::dvec3(v.forward), v.near_distance);
        const gsv::MeshData cap = proxy->proxy->near_cap(proxy->box.texture_plane(near_model));
        if (!cap.indices.empty()) gsv::GpuMesh(cap, kit().profile()).draw();
    }
    // Geometry in front of the entry point: the entry becomes the geometry too, entry == exit, no ray.
    if (occluder) occluder->draw();

    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDisable(GL_DEPTH_TEST);
    set_output("entry", entry_);
    set_output("exit", exit_);
}

}  // namespace lab06
