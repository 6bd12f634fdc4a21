// Lab 06, compositing module: maximum intensity projection. The largest intensity along the ray is
// classified once, at the end, so MIP needs neither gradient nor shading nor a lookup per sample.
#pragma once
#include "gsv/not_done.glsl"
#include "raycast_common.glsl"

RcState rcStartMip(RcRay ray) { return rcStartState(); }

void rcCompositeMip(inout RcState s, RcRay ray, float t, float intensity) {
    // TODO(L06-T4): keep the largest intensity (s.value) and the t where it was (s.hitT, for the depth).
    s.hitT = t;
}

// The maximum can come last: a MIP ray always runs to its exit.
bool rcTerminateMip(RcState s) { return false; }

vec4 rcFinishMip(RcState s) {
    // TODO(L06-T4): classify the maximum once, and return it premultiplied by its opacity.
    return vec4(kNotDone, 1.0);
}
