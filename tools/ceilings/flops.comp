// gsv-ceilings: flops.frag's chains in a compute shader, one invocation a pixel of a SIDE x SIDE grid.
layout(local_size_x = 8, local_size_y = 8) in;
uniform vec4 uA;
uniform vec4 uB;
layout(std430, binding = 0) writeonly buffer Sums { vec4 sums[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    vec4 x0 = vec4(vec2(pixel) / float(SIDE), 0.0, 1.0), x1 = x0 + 1.0, x2 = x0 + 2.0, x3 = x0 + 3.0;
    for (int i = 0; i < ITERATIONS; ++i) {
        x0 = x0 * uA + uB;
        x1 = x1 * uA + uB;
        x2 = x2 * uA + uB;
        x3 = x3 * uA + uB;
    }
    sums[pixel.y * uint(SIDE) + pixel.x] = x0 + x1 + x2 + x3;
}
