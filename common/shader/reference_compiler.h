#pragma once
// The Khronos reference GLSL front end (glslangValidator, Debian's glslang-tools), where it is installed. Mesa files
// some errors (a wrong-type assignment among them) under source string 0 whatever #line says, so an error inside an
// included file would be blamed on the main file; glslangValidator honours #line and places it.
#include "common/gl/gl_version.h"

#include <optional>
#include <string>

namespace gsv {

// Its log for `text` compiled as `stage`, or nothing where the tool is not installed or cannot be run.
std::optional<std::string> reference_compiler_log(const std::string& text, ShaderStage stage);

}  // namespace gsv
