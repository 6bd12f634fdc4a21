#pragma once
// What a starter draws where a TODO is still open: magenta, a colour no correct rendering produces. Defined once,
// here: shaders `#include "gsv/not_done.glsl"`, a file the shader preprocessor writes from this constant, and the
// grader recognises the colour from it.
#include <array>
#include <cstdint>
#include <string>

namespace gsv {

inline constexpr std::array<std::uint8_t, 3> kNotDoneRgb{255, 0, 255};

inline constexpr const char* kNotDoneInclude = "gsv/not_done.glsl";

inline std::string not_done_glsl() {
    const auto unit = [](std::uint8_t c) { return c == 255 ? std::string("1.0") : std::to_string(c / 255.0); };
    return "// What a starter draws where a TODO is still open: a colour no correct rendering produces (written by the\n"
           "// kit from gsv::kNotDoneRgb, which the grader recognises).\n"
           "#pragma once\n"
           "const vec3 kNotDone = vec3(" +
           unit(kNotDoneRgb[0]) + ", " + unit(kNotDoneRgb[1]) + ", " + unit(kNotDoneRgb[2]) + ");\n";
}

}  // namespace gsv
