// gsv-ceilings: FP32 rate in a fragment shader: four independent vec4 multiply-add chains (so that one chain's latency
// does not decide), ITERATIONS times: 32 flops an iteration. uA and uB are uniforms, so nothing folds at compile time.
uniform vec4 uA;
uniform vec4 uB;
in vec2 vTexCoord;
out vec4 fColor;

void main() {
    vec4 x0 = vec4(vTexCoord, 0.0, 1.0), x1 = x0 + 1.0, x2 = x0 + 2.0, x3 = x0 + 3.0;
    for (int i = 0; i < ITERATIONS; ++i) {
        x0 = x0 * uA + uB;
        x1 = x1 * uA + uB;
        x2 = x2 * uA + uB;
        x3 = x3 * uA + uB;
    }
    fColor = (x0 + x1 + x2 + x3) * 0.001;
}
