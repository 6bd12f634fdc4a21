#pragma once
// The GL version and profile a run asks for; the shader loader derives the #version line from them.
#include <string>

namespace gsv {

enum class Profile { Core, Compat };

struct GlVersion {
    int major = 4;
    int minor = 1;

    // GLSL's number for this GL version (3.3 -> 330, 4.1 -> 410); GL 3.0-3.2 used GLSL 1.30-1.50.
    int glsl() const {
        if (major == 3 && minor < 3) return 130 + 10 * minor;
        return major * 100 + minor * 10;
    }
    bool at_least(int maj, int min) const { return major > maj || (major == maj && minor >= min); }
    std::string str() const { return std::to_string(major) + "." + std::to_string(minor); }
    friend bool operator==(GlVersion a, GlVersion b) { return a.major == b.major && a.minor == b.minor; }
    friend bool operator<(GlVersion a, GlVersion b) { return a.major != b.major ? a.major < b.major : a.minor < b.minor; }
};

inline const char* profile_name(Profile p) { return p == Profile::Core ? "core" : "compat"; }

enum class ShaderStage { Vertex, TessControl, TessEval, Geometry, Fragment, Compute };

}  // namespace gsv
