// bufferFetch: texel `index` of a buffer texture (common/gl/buffer_texture.h), declared with the type
// BUFFER_SAMPLER: `uniform BUFFER_SAMPLER uValues;`.
// Inputs: the sampler, the texel's index. Returns: the texel (R32F: the value in .r).
// OpenGL ES has buffer textures only from 3.2, WebGL 2 none: before 3.2 the kit stores the same texels as the
// rows of a 2D texture kBufferRowTexels wide (GSV_NO_BUFFER_TEXTURES, from the ES prelude), and the index
// becomes a column and a row. Either way one texelFetch, no filtering.
#pragma once

#ifdef GSV_NO_BUFFER_TEXTURES
#define BUFFER_SAMPLER sampler2D
const int kBufferRowTexels = 2048;  // BufferTexture::kRowTexels

vec4 bufferFetch(sampler2D values, int index) {
    return texelFetch(values, ivec2(index % kBufferRowTexels, index / kBufferRowTexels), 0);
}
#else
#define BUFFER_SAMPLER samplerBuffer

vec4 bufferFetch(samplerBuffer values, int index) { return texelFetch(values, index); }
#endif
