#pragma once
// Where a lab's parameters reach its shaders: each runtime parameter as its uniform (u<Name>), each compile-time
// one as its #define. Both note what they read for change tracking (common/params/change_tracker.h): an active
// uniform of a program in use, and every compile-time parameter, compiled into every program.
#include "common/params/params.h"
#include "common/shader/shader_program.h"
#include "common/shader/shader_source.h"

#include <vector>

namespace gsv {

// The #defines of the compile-time parameters: a Bool when on, "1"; a Choice its index and NAME_VALUE 1; an Int
// or Float its value; a Vec3 vec3(x,y,z).
std::vector<ShaderDefine> param_defines(const Params& params);

// Sets every runtime parameter's uniform on `program`, which must be in use. Throws where the program samples a
// texture through a parameter's uniform (a shader edited since check_param_uniforms passed it).
void apply_param_uniforms(const Params& params, const ShaderProgram& program);

// Refuses, in one line naming both, a runtime parameter whose uniform is one of `uniforms` (a program's, `program`
// in messages) that its value cannot set: a sampler (a parameter `field` beside a texture uField), a matrix, a
// vector of another size. The parameter is renamed, or declared without_uniform() where only the lab reads it.
void check_param_uniforms(const Params& params, const std::vector<UniformDeclaration>& uniforms, const std::string& program);

}  // namespace gsv
