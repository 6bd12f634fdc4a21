// The instrumented build that counts a lab's texture fetches (issue 44's independent count of Lab::frame_work); off
// unless the environment sets GSV_COUNT_FETCHES=1, which the lab framework passes on as a define of the same name and
// answers by binding an atomic counter buffer (common/app/fetch_counter.h). Every texture() and textureLod() lookup of
// a fragment or compute shader adds one to the counter of its sampler's kind: 2D at offset 0, 3D at 4, 2D array at 8.
// It changes what the built-in lookups cost, never what they return.
#if defined(GSV_COUNT_FETCHES) && (defined(GSV_STAGE_FRAGMENT) || defined(GSV_STAGE_COMPUTE))
#if GSV_GLSL_VERSION < 420 || defined(GSV_PROFILE_ES)
#error "GSV_COUNT_FETCHES needs GLSL 4.20 (atomic counters): run the lab with --gl 4.5"
#endif
#ifdef GSV_TEXEL_SNAP
#error "GSV_COUNT_FETCHES and GSV_TEXEL_SNAP both redefine texture(): set one of them"
#endif
layout(binding = 0, offset = 0) uniform atomic_uint gsvFetches2D;
layout(binding = 0, offset = 4) uniform atomic_uint gsvFetches3D;
layout(binding = 0, offset = 8) uniform atomic_uint gsvFetches2DArray;
vec4 gsvCountedTexture(sampler2D s, vec2 p) { atomicCounterIncrement(gsvFetches2D); return texture(s, p); }
vec4 gsvCountedTexture(sampler3D s, vec3 p) { atomicCounterIncrement(gsvFetches3D); return texture(s, p); }
vec4 gsvCountedTexture(sampler2DArray s, vec3 p) { atomicCounterIncrement(gsvFetches2DArray); return texture(s, p); }
vec4 gsvCountedTextureLod(sampler2D s, vec2 p, float lod) { atomicCounterIncrement(gsvFetches2D); return textureLod(s, p, lod); }
vec4 gsvCountedTextureLod(sampler3D s, vec3 p, float lod) { atomicCounterIncrement(gsvFetches3D); return textureLod(s, p, lod); }
vec4 gsvCountedTextureLod(sampler2DArray s, vec3 p, float lod) {
    atomicCounterIncrement(gsvFetches2DArray);
    return textureLod(s, p, lod);
}
// After the functions above, whose own lookups stay the built-in ones.
#define texture(s, p) gsvCountedTexture(s, p)
#define textureLod(s, p, lod) gsvCountedTextureLod(s, p, lod)
#endif
