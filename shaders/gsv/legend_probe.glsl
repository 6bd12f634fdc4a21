// The value a legend probe colours at this fragment (common/app/legend_probe.h): the probe draws one row, one
// pixel per value, and reads the pixel's value from a one-row float texture. A lab's probe shader includes this
// and its own colour function, and writes that function's colour for legendValue(), unlit.
#pragma once

uniform sampler2D uLegendValues;

float legendValue() {
    return texelFetch(uLegendValues, ivec2(int(gl_FragCoord.x), 0), 0).r;
}
