// Lab 02: one step along a streamline of the flow texture.
#pragma once
#include "gsv/math.glsl"

uniform sampler2D uFlow;  // velocity in texels per step (x, y in red and green), float, linear filtering

vec2 flowAt(vec2 st) {
    return texture(uFlow, st).xy;
}

// Normalised stepping moves one texel per step whatever the speed, so slow regions get streaks as
// long as fast ones.
vec2 stepDirection(vec2 v) {
#ifdef EFFECT_NORMALIZED
    // TODO(L02-T4): a unit vector along v (one texel per step, however slow the flow). At a zero of
    // the field (the centre of a source, a vortex, a saddle) there is no direction: stay put rather
    // than divide by zero.
    // (normalize(0) is NaN; a NaN position fails every comparison, so only streamlineContinues
    // would stop it, and a GPU need not even honour that.)
//@solution L02-T4
    return safeNormalize(v, vec2(0.0));
//@starter
//    return v;
//@end
#else
    return v;
#endif
}

// One step forward (direction +1) or backward (-1), in texture coordinates.
vec2 advance(vec2 st, float direction, vec2 texel) {
#ifdef STEP_MIDPOINT
    // TODO(L02-T5): the second-order (midpoint) step: a half step to the midpoint, then the whole
    // step with the velocity found there. Circles stay circles far longer than with Euler.
//@solution L02-T5
    vec2 halfStep = st + 0.5 * direction * stepDirection(flowAt(st)) * texel;
    return st + direction * stepDirection(flowAt(halfStep)) * texel;
//@starter
//    return st + direction * stepDirection(flowAt(st)) * texel;
//@end
#else
    return st + direction * stepDirection(flowAt(st)) * texel;
#endif
}

// TODO(L02-T3): a streamline that leaves the field ends there: samples outside [0,1]^2 are not
// counted (the texture would clamp them to the border texel and smear it into a streak).
bool streamlineContinues(vec2 st) {
//@solution L02-T3
    return all(greaterThanEqual(st, vec2(0.0))) && all(lessThanEqual(st, vec2(1.0)));
//@starter
//    return true;
//@end
}
