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
//@solution L06-T5
    if (intensity < uIsoValue) {
        s.value = intensity;  // the previous sample for the next call
        return;
    }
    float hit = t;
    if (t > ray.step) {
        // previous < iso <= intensity, so rise > 0; the guard keeps a sample pair that both equal the
        // iso value (0 / 0) from ever reaching the division, however this rule is changed.
        float rise = intensity - s.value;
        float w = rise > 0.0 ? clamp((uIsoValue - s.value) / rise, 0.0, 1.0) : 1.0;
        hit = t - (1.0 - w) * ray.step;
    }
    vec3 p = rcPosition(ray, hit);
    // The surface's value is uIsoValue by construction: classify that, not a resampled intensity.
    vec4 color = RC_CLASSIFY(uIsoValue);
    s.color = vec4(RC_SHADE(color.rgb, RC_GRADIENT(p), p), 1.0);
    s.hitT = hit;
//@starter
//    s.color = vec4(kNotDone, 1.0);
//    s.hitT = t;
//@end
}

bool rcTerminateIso(RcState s) { return s.hitT >= 0.0; }

vec4 rcFinishIso(RcState s) { return s.color; }
