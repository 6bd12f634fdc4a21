#pragma once
// The kit's version, one for every binary: the project's VERSION in the top CMakeLists.txt, compiled into
// version.cpp alone so that raising it rebuilds one file.
#include <string>

namespace gsv {

const char* kit_version();
// "<program> (GPU Shaders for Visualization) <version>": what --version prints.
std::string version_line(const std::string& program);

}  // namespace gsv
