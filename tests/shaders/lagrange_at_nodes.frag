// Test shader for lab 07's spectral.glsl: pixel (i, j) of a (DEGREE + 1) x (DEGREE + 2) target evaluates
// element 0 at (x_i, x_j), exactly a node, as the uniforms hold it; the extra top row evaluates
// just beside the nodes, x_i plus one float ulp, where the barycentric sum is closest to 0/0.
#include "spectral.glsl"

out vec4 fColor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float xi = uNodes[p.x];
    float eta = uNodes[min(p.y, DEGREE)];
    if (p.y > DEGREE) {
        xi = uintBitsToFloat(floatBitsToUint(xi) + 1u);
        eta = 0.3;
    }
    fColor = vec4(elementValue(0, vec2(xi, eta)), xi, eta, 1.0);
}
