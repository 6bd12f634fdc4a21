// Lab 06, compositing module: first hit points. The colour is the texture coordinate of the first sample
// the classification makes visible (alpha > 0), alpha 1: what a later pass (or a shadow ray) starts from.
// Calls the RC_CLASSIFY placeholder, which must be defined before this file is included.
#pragma once
#include "raycast_common.glsl"

RcState rcStartFhp(RcRay ray) { return rcStartState(); }

void rcCompositeFhp(inout RcState s, RcRay ray, float t, float intensity) {
    if (RC_CLASSIFY(intensity).a <= 0.0) return;
    s.color = vec4(rcPosition(ray, t), 1.0);
    s.hitT = t;
}

bool rcTerminateFhp(RcState s) { return s.hitT >= 0.0; }

vec4 rcFinishFhp(RcState s) { return s.color; }
