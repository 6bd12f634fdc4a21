// Lab 04: the height colours for the legend (gsv/legend_probe.glsl), from the terrain's own heightColor, unlit.
#include "gsv/legend_probe.glsl"
#include "color.glsl"

out vec4 fColor;

void main() {
    fColor = vec4(heightColor(legendValue()), 1.0);
}
