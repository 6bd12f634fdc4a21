// Lab 03: writes the flow that flowAt() returns, unchanged, into a float target one texel per flow
// texel, so the lab can compare what the GPU sampled with what it stored.
#include "flow_time.glsl"

in vec2 vTexCoord;
out vec4 fColor;

void main() {
    fColor = vec4(flowAt(vTexCoord), 0.0, 1.0);
}
