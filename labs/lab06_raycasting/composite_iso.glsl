// Lab 06, compositing module: the isosurface v = uIsoValue, as an opaque shaded surface. Calls the
// RC_CLASSIFY, RC_GRADIENT and RC_SHADE placeholders, which must be defined before this file is included.
#pragma once
#include "gsv/not_done.glsl"
#include "raycast_common.glsl"

uniform float uIsoValue;

// The surface bounds the inside, {v >= uIsoValue}; the ray hits it at its first sample inside. If the
// sample before was outside, the crossing lies between the two, where their linear interpolation reaches
// uIsoValue; a ray that starts inside (a cut through the object) is hit at its first sample.
RcState rcStartIso(RcRay ray) { return rcStartState(); }

void rcCompositeIso(inout RcState s, RcRay ray, float t, float intensity) {
    // TODO(L06-T5): the first sample at or above uIsoValue is a hit. Between it and the sample before
    // (s.value, if there was one) place the hit where their linear interpolation reaches uIsoValue, never
    // dividing 0 by 0; classify uIsoValue, shade it there, opaque, and record s.hitT. Below the value,
    // remember the sample in s.value for the next call.
    s.color = vec4(kNotDone, 1.0);
    s.hitT = t;
}

bool rcTerminateIso(RcState s) { return s.hitT >= 0.0; }

vec4 rcFinishIso(RcState s) { return s.color; }
