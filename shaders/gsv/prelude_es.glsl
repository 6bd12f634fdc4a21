// Kit prelude for OpenGL ES 3.x (and so WebGL 2), spliced in before every lab shader.
// GLSL ES gives no default precision to floats in fragment shaders, to 3D and array samplers anywhere, or
// to images: the kit asks for highp everywhere, so a lab's numbers mean what they mean on the desktop
// (mediump is 16-bit on phones; llvmpipe computes everything at 32 bits either way).
precision highp float;
precision highp int;
precision highp sampler2D;
precision highp sampler3D;
precision highp samplerCube;
precision highp sampler2DArray;
precision highp sampler2DShadow;
precision highp isampler2D;
precision highp isampler3D;
precision highp usampler2D;
precision highp usampler3D;
#if GSV_GLSL_VERSION >= 310
precision highp image2D;
precision highp image3D;
precision highp iimage2D;
precision highp uimage2D;
#endif
#if GSV_GLSL_VERSION >= 320
precision highp samplerBuffer;
precision highp isamplerBuffer;
precision highp usamplerBuffer;
#endif
// What a version lacks and a lab can stand in for, the kit's header defines from common/gl/gl_features.h:
// GSV_NO_BUFFER_TEXTURES (ES 3.0, 3.1: rows of a 2D texture, read through gsv/buffer_fetch.glsl) and
// GSV_NO_PRIMITIVE_ID (no gl_PrimitiveID in fragment shaders: the lab passes its own id, flat).

// The names the kit's shaders share, as uniforms and attributes: ES has no fixed-function built-ins either.
#include "gsv/prelude_core.glsl"
