// Lab 04: writes terrain_normal() unchanged into a float target, one fragment per height sample, so the
// lab can measure its angle from the exact normal.
#include "normal.glsl"

in vec2 vTexCoord;
out vec4 fColor;

void main() {
    fColor = vec4(terrain_normal(vTexCoord), 1.0);
}
