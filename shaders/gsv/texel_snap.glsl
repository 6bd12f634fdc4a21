// The "8-bit filter weights" stand-in of the margin table (scripts/kit margins, grader/src/margins/margins.h); off unless the
// environment sets GSV_TEXEL_SNAP, which the lab framework passes on as a define of the same name (common/app/app.cpp).
// GPUs filter textures with fixed-point weights, typically 8 bits of sub-texel position, where llvmpipe and softpipe
// filter in float. With GSV_TEXEL_SNAP = N every texture() and textureLod() lookup of a 2D, 3D or array texture has
// its coordinate snapped to 1/N of a texel before it is filtered (N = 256: 8 bits), so a filter weight takes only
// N + 1 values, as on such a GPU. It changes what the built-in lookups do: no lab shader uses it.
#ifdef GSV_TEXEL_SNAP
// `p` in texture space [0, 1]; the sample position in texels (centres at k + 0.5) snapped to 1/N, back in [0, 1].
vec2 gsvSnapTexel(vec2 p, vec2 size) {
    return (floor((p * size - 0.5) * float(GSV_TEXEL_SNAP) + 0.5) / float(GSV_TEXEL_SNAP) + 0.5) / size;
}
vec3 gsvSnapTexel(vec3 p, vec3 size) {
    return (floor((p * size - 0.5) * float(GSV_TEXEL_SNAP) + 0.5) / float(GSV_TEXEL_SNAP) + 0.5) / size;
}
vec4 gsvSnappedTexture(sampler2D s, vec2 p) { return texture(s, gsvSnapTexel(p, vec2(textureSize(s, 0)))); }
vec4 gsvSnappedTexture(sampler3D s, vec3 p) { return texture(s, gsvSnapTexel(p, vec3(textureSize(s, 0)))); }
// An array's layer is chosen, not filtered: only the coordinates within the layer are snapped.
vec4 gsvSnappedTexture(sampler2DArray s, vec3 p) {
    return texture(s, vec3(gsvSnapTexel(p.xy, vec2(textureSize(s, 0).xy)), p.z));
}
vec4 gsvSnappedTextureLod(sampler2D s, vec2 p, float lod) {
    return textureLod(s, gsvSnapTexel(p, vec2(textureSize(s, int(lod)))), lod);
}
vec4 gsvSnappedTextureLod(sampler3D s, vec3 p, float lod) {
    return textureLod(s, gsvSnapTexel(p, vec3(textureSize(s, int(lod)))), lod);
}
vec4 gsvSnappedTextureLod(sampler2DArray s, vec3 p, float lod) {
    return textureLod(s, vec3(gsvSnapTexel(p.xy, vec2(textureSize(s, int(lod)).xy)), p.z), lod);
}
// After the functions above, whose own lookups stay the built-in ones.
#define texture(s, p) gsvSnappedTexture(s, p)
#define textureLod(s, p, lod) gsvSnappedTextureLod(s, p, lod)
#endif
