#pragma once
// The GL version and profile a run asks for; the shader loader derives the #version line from them.
// Three profiles: desktop core, desktop compatibility (the seeds' gl_ModelViewProjectionMatrix...), and
// OpenGL ES 3.x, whose 3.0 is what WebGL 2 offers. A GlVersion is read against its profile: 3.1 is an ES
// version or an old desktop one.
#include <string>

namespace gsv {

enum class Profile { Core, Compat, Es };

struct GlVersion {
    int major = 4;
    int minor = 1;

    // GLSL's number for this desktop GL version (3.3 -> 330, 4.1 -> 410); GL 3.0-3.2 used GLSL 1.30-1.50.
    int glsl() const {
        if (major == 3 && minor < 3) return 130 + 10 * minor;
        return major * 100 + minor * 10;
    }
    // GLSL's number in a profile: GLSL ES follows its API's version (ES 3.0 -> 300 es, 3.2 -> 320 es).
    int glsl(Profile profile) const { return profile == Profile::Es ? major * 100 + minor * 10 : glsl(); }
    bool at_least(int maj, int min) const { return major > maj || (major == maj && minor >= min); }
    std::string str() const { return std::to_string(major) + "." + std::to_string(minor); }
    friend bool operator==(GlVersion a, GlVersion b) { return a.major == b.major && a.minor == b.minor; }
    friend bool operator<(GlVersion a, GlVersion b) { return a.major != b.major ? a.major < b.major : a.minor < b.minor; }
};

inline const char* profile_name(Profile p) {
    return p == Profile::Core ? "core" : p == Profile::Compat ? "compat" : "es";
}
// Only the compatibility profile has the fixed-function matrix stack and vertex arrays; core and ES feed the
// kit's shared names (uModelViewMatrix, aVertex...) as uniforms and generic attributes.
inline bool has_fixed_function(Profile p) { return p == Profile::Compat; }
// "OpenGL 4.1" or "OpenGL ES 3.0": how messages name a version in its profile.
inline std::string api_name(Profile p, GlVersion v) {
    return std::string(p == Profile::Es ? "OpenGL ES " : "OpenGL ") + v.str();
}

enum class ShaderStage { Vertex, TessControl, TessEval, Geometry, Fragment, Compute };

}  // namespace gsv
