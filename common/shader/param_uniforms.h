#pragma once
// Where a lab's parameters reach its shaders: each runtime parameter as its uniform (u<Name>), each compile-time
// one as its #define. Both note what they read for change tracking (common/params/change_tracker.h): an active
// uniform of a program in use, and every compile-time parameter, compiled into every program.
#include "common/params/params.h"
#include "common/shader/shader_source.h"

#include <vector>

namespace gsv {

class ShaderProgram;

// The #defines of the compile-time parameters: a Bool when on, "1"; a Choice its index and NAME_VALUE 1; an Int
// or Float its value; a Vec3 vec3(x,y,z).
std::vector<ShaderDefine> param_defines(const Params& params);

// Sets every runtime parameter's uniform on `program`, which must be in use; a sampler of that name is left on its
// texture unit.
void apply_param_uniforms(const Params& params, const ShaderProgram& program);

}  // namespace gsv
