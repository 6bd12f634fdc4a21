// Lab 06: raw classification for the legend (gsv/legend_probe.glsl): the intensity as the opacity of white.
#include "gsv/legend_probe.glsl"
#include "classify_raw.glsl"

out vec4 fColor;

void main() {
    fColor = rcClassifyRaw(legendValue());
}
