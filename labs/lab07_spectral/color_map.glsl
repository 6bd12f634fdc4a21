// Lab 07: a field value to a colour over the range [uRangeMin, uRangeMax]: blue through white to red, the
// diverging map the seed's figures use. Narrowing the range spreads one element's values over all of it.
#pragma once
#include "gsv/not_done.glsl"

uniform float uRangeMin;
uniform float uRangeMax;

vec3 colorMap(float value) {
    // TODO(L07-T3): t = (value - uRangeMin) / (uRangeMax - uRangeMin); below 0 or above 1 (outside the
    // range) draw the end colour darkened to half, so a narrowed range shows where it is exceeded; between,
    // blend blue (0) -> white (0.5) -> red (1). An empty range (max <= min) must not divide by zero: draw grey.
    const vec3 low = vec3(0.23, 0.30, 0.75), middle = vec3(0.87, 0.87, 0.87), high = vec3(0.71, 0.02, 0.15);
    return kNotDone;
}
