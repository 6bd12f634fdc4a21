// Lab 05: the speed colours for the legend (gsv/legend_probe.glsl), from the same speedColor the compute stage
// writes into each particle's colour.
#include "gsv/legend_probe.glsl"
#include "speed_color.glsl"

out vec4 fColor;

void main() {
    fColor = vec4(speedColor(legendValue()), 1.0);
}
