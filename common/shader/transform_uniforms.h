#pragma once
// A draw's transforms (common/scene/transforms.h) handed to its program: as uModelViewProjectionMatrix,
// uModelViewMatrix, uProjectionMatrix and uNormalMatrix in core and ES, or loaded into the fixed-function matrix stacks
// that feed gl_ModelViewProjectionMatrix & co. in compat.
#include "common/gl/gl_version.h"
#include "common/scene/transforms.h"
#include "common/shader/shader_program.h"

namespace gsv {

// Must be called with `program` in use.
void apply_transforms(const ShaderProgram& program, const Transforms& transforms, Profile profile);

}  // namespace gsv
