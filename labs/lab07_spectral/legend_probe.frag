// Lab 07: the field's colours for the legend (gsv/legend_probe.glsl), from the same colorMap the elements use,
// in range and out of it.
#include "gsv/legend_probe.glsl"
#include "color_map.glsl"

out vec4 fColor;

void main() {
    fColor = vec4(colorMap(legendValue()), 1.0);
}
