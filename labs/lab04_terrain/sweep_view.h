#pragma once
// What lab 04 shows, read-only, to the sweep plan that measures it (the instructor's reference/lab04_terrain/): the
// terrain the last frame drew and how the lab hands it to a program, so the plan can read the shader's normals.
#include "common/shader/shader_program.h"
#include "terrain_source.h"

namespace lab04 {

class SweepView {
public:
    virtual ~SweepView() = default;
    virtual const Terrain& terrain() const = 0;
    // Binds the heights and sets the terrain's placement, as for the lab's own programs.
    virtual void set_terrain_uniforms(const gsv::ShaderProgram& program) const = 0;
};

}  // namespace lab04
