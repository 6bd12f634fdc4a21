#include "common/core/version.h"

namespace gsv {

const char* kit_version() { return GSV_VERSION; }

std::string version_line(const std::string& program) {
    return program + " (GPU Shaders for Visualization) " + kit_version();
}

}  // namespace gsv
