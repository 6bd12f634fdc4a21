// Kit prelude for the compatibility profile, spliced in before every lab shader.
// The compatibility profile already tracks the matrix stack and vertex arrays in gl_* built-ins, so
// the kit's shared names become aliases for them rather than new declarations: the host's legacy
// calls then feed the same shader text that the core prelude (prelude_core.glsl) serves with uniforms.
#define uModelViewProjectionMatrix gl_ModelViewProjectionMatrix
#define uModelViewMatrix gl_ModelViewMatrix
#define uProjectionMatrix gl_ProjectionMatrix
#define uNormalMatrix gl_NormalMatrix

// gl_Vertex and friends are vertex-shader built-ins only.
#ifdef GSV_STAGE_VERTEX
#define aVertex gl_Vertex
#define aNormal gl_Normal
#define aTexCoord0 gl_MultiTexCoord0
#endif

// Off unless the margin table's 8-bit filter stand-in asks for it (GSV_TEXEL_SNAP).
#include "gsv/texel_snap.glsl"
// Off unless the instrumented build that counts texture fetches asks for it (GSV_COUNT_FETCHES).
#include "gsv/fetch_count.glsl"
