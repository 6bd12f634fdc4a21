#pragma once
// The vertex attribute slots every kit mesh fills (common/gl/gpu_mesh.h) and every core-profile program binds its
// aVertex, aNormal and aTexCoord0 to before linking (common/shader/shader_program.cpp): the one agreement between a
// mesh and a program, so it stands below both.
#include "common/gl/gl.h"

namespace gsv {

enum AttributeSlot : GLuint { kVertexSlot = 0, kNormalSlot = 1, kTexCoord0Slot = 2 };

}  // namespace gsv
