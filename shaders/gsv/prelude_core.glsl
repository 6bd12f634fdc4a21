// Kit prelude for the core profile, spliced in before every lab shader.
// Core GLSL has no fixed-function built-ins, so the names the kit's shaders share are declared here
// as ordinary uniforms and attributes that the host sets by name. prelude_compat.glsl maps the same
// names onto the compatibility built-ins, which is what lets one shader file build in both profiles.
uniform mat4 uModelViewProjectionMatrix;
uniform mat4 uModelViewMatrix;
uniform mat4 uProjectionMatrix;
uniform mat3 uNormalMatrix;

// Attributes exist only as vertex-shader inputs; any other stage would see stray varyings.
#ifdef GSV_STAGE_VERTEX
in vec4 aVertex;
in vec3 aNormal;
in vec4 aTexCoord0;
#endif

// Off unless the margin table's 8-bit filter stand-in asks for it (GSV_TEXEL_SNAP).
#include "gsv/texel_snap.glsl"
// Off unless the instrumented build that counts texture fetches asks for it (GSV_COUNT_FETCHES).
#include "gsv/fetch_count.glsl"
