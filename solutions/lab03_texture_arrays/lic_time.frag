// Lab 03 fragment stage: line integral convolution through the flow at the playhead. The streamline
// tracing is lab 02's (midpoint steps, ending at the border); what is new is where the flow comes
// from: flowAt() reads the time slices (flow_time.glsl).
#include "flow_time.glsl"
#include "gsv/not_done.glsl"

uniform sampler2D uNoise;
uniform int uLength;      // steps each way
uniform vec2 uFlowTexel;  // one flow texel in texture coordinates: velocities are in flow texels per step

in vec2 vTexCoord;
out vec4 fColor;

bool inside(vec2 st) { return all(greaterThanEqual(st, vec2(0.0))) && all(lessThanEqual(st, vec2(1.0))); }

void main() {
    float sum = texture(uNoise, vTexCoord).r;
    float count = 1.0;
    for (int direction = -1; direction <= 1; direction += 2) {
        vec2 st = vTexCoord;
        for (int i = 0; i < uLength; ++i) {
            vec2 halfWay = st + 0.5 * float(direction) * flowAt(st) * uFlowTexel;
            st += float(direction) * flowAt(halfWay) * uFlowTexel;
            if (!inside(st)) break;
            sum += texture(uNoise, st).r;
            count += 1.0;
        }
    }
    fColor = gNotDone ? vec4(kNotDone, 1.0) : vec4(vec3(sum / count), 1.0);
}
