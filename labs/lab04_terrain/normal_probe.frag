// Lab 04: writes terrainNormal() unchanged into a float target, one fragment per height sample, so the
// lab can measure its angle from the exact normal.
#include "normal.glsl"

in vec2 vTexCoord;
out vec4 fColor;

void main() {
    fColor = vec4(terrainNormal(vTexCoord), 1.0);
}
