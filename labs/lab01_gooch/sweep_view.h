#pragma once
// What lab 01 lends the sweep plan that measures it (the instructor's reference/lab01_gooch/): whether the exact
// sphere stands for what it draws, and its own drawing, with any program, from the same camera and light.
#include "common/app/app.h"
#include "common/scene/transforms.h"
#include "common/shader/shader_library.h"

#include <glm/glm.hpp>

namespace lab01 {

class SweepView {
public:
    virtual ~SweepView() = default;
    // The sphere, whole, scaled equally on every axis and without silhouettes: what exact_sphere.frag draws.
    virtual bool exact_sphere_applies() const = 0;
    virtual bool lights_each_fragment() const = 0;
    virtual const gsv::ShaderLibrary::Entry& shade_program() const = 0;
    virtual glm::vec4 background() const = 0;
    // Clears to `background` and draws the mesh with `entry`, as the lab draws its frame.
    virtual void draw(gsv::LabKit& kit, const gsv::Frame& frame, const gsv::ShaderLibrary::Entry& entry,
                      glm::vec4 background) = 0;
    // Sets the camera's transforms and the light on `program`, as draw() does; returns the transforms.
    virtual gsv::Transforms set_view(gsv::LabKit& kit, const gsv::ShaderProgram& program, const gsv::Frame& frame) const = 0;
};

}  // namespace lab01
