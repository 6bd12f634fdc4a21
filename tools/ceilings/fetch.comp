// gsv-ceilings: fetch.frag's lookups in a compute shader, one invocation a pixel of a SIDE x SIDE grid, explicit level
// 0 (a compute shader has no derivatives); each invocation writes its sum, 16 bytes against FETCHES lookups.
layout(local_size_x = 8, local_size_y = 8) in;
#if defined(DIM_3D)
uniform sampler3D uTexture;
#elif defined(DIM_ARRAY)
uniform sampler2DArray uTexture;
#else
uniform sampler2D uTexture;
#endif
uniform vec3 uStep;
layout(std430, binding = 0) writeonly buffer Sums { vec4 sums[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    vec4 sum = vec4(0.0);
    vec3 p = vec3((vec2(pixel) + 0.5) / float(SIDE), 0.0);
    for (int i = 0; i < FETCHES; ++i) {
        p += uStep;
#if defined(DIM_3D)
        sum += textureLod(uTexture, p, 0.0);
#elif defined(DIM_ARRAY)
        sum += textureLod(uTexture, vec3(p.xy, 0.0), 0.0);
#else
        sum += textureLod(uTexture, p.xy, 0.0);
#endif
    }
    sums[pixel.y * uint(SIDE) + pixel.x] = sum;
}
