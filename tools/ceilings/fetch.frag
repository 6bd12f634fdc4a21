// gsv-ceilings: bilinear lookups in a fragment shader, FETCHES a fragment, along a line of short steps (uStep) as LIC
// and a ray caster step: neighbouring fragments read neighbouring texels, and a fragment's lookups the same few, so
// the caches hold them and the filtering is measured. The loop's count is a constant: unrolled, it ran twice as fast
// on llvmpipe as with the count in a uniform.
// Summed into the colour, so that no lookup is dead code. DIM_2D, DIM_ARRAY or DIM_3D picks the sampler.
#if defined(DIM_3D)
uniform sampler3D uTexture;
#elif defined(DIM_ARRAY)
uniform sampler2DArray uTexture;
#else
uniform sampler2D uTexture;
#endif
uniform vec3 uStep;  // one texel along a fixed slanted direction, in texture coordinates

in vec2 vTexCoord;
out vec4 fColor;

void main() {
    vec4 sum = vec4(0.0);
    vec3 p = vec3(vTexCoord, 0.0);
    for (int i = 0; i < FETCHES; ++i) {
        p += uStep;
#if defined(DIM_3D)
        sum += texture(uTexture, p);
#elif defined(DIM_ARRAY)
        sum += texture(uTexture, vec3(p.xy, 0.0));
#else
        sum += texture(uTexture, p.xy);
#endif
    }
    fColor = sum * (1.0 / float(FETCHES));
}
