#pragma once
// A driver's compile or link log told in the student's terms: the kit hands GL one string made of many files
// (shader_source.h), and a driver names places in it by source-string number and line, in its own format (Mesa's,
// NVIDIA's, glslang's); each message is put back at the file and line the student wrote, with that line quoted.
#include "common/shader/shader_source.h"

#include <string>

namespace gsv {

// Rewrites a driver's compile/link info log so each message names the original file and line and
// is followed by that source line indented by 4 spaces. Lines it cannot parse pass through unchanged. A message
// the driver files under no file is placed by glslangValidator where it is installed (common/shader/reference_compiler.h),
// else in the main file, saying so.
std::string translate_compile_log(const std::string& log, const ShaderSource& source, ShaderStage stage = ShaderStage::Fragment);

}  // namespace gsv
