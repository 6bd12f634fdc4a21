// Lab 05: a particle's colour from its speed, slow blue through cyan, green and yellow to fast red.
#pragma once
#include "gsv/not_done.glsl"

uniform float uSpeedScale;  // the speed drawn red

vec3 speedColor(float speed) {
    // TODO(L05-T6): map speed / uSpeedScale, clamped to [0, 1], onto the five colours below, mixing
    // linearly between neighbours (0 is the first colour, 1 the last). A particle at rest is blue, not NaN.
    const vec3 ramp[5] = vec3[5](vec3(0.10, 0.20, 0.90), vec3(0.00, 0.75, 0.90), vec3(0.20, 0.85, 0.25),
                                 vec3(0.95, 0.85, 0.10), vec3(0.90, 0.15, 0.10));
//@solution L05-T6
    float x = clamp(speed / uSpeedScale, 0.0, 1.0) * 4.0;
    int i = min(int(x), 3);
    return mix(ramp[i], ramp[i + 1], x - float(i));
//@starter
//    return kNotDone;
//@end
}
