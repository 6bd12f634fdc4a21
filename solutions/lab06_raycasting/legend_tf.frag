// Lab 06: the transfer function for the legend (gsv/legend_probe.glsl): colour and opacity as the
// classification module returns them, from the ray caster's own table.
#include "gsv/legend_probe.glsl"
#include "classify_tf.glsl"

out vec4 fColor;

void main() {
    fColor = rcClassifyTf(legendValue());
}
