// Lab 06, compositing module: maximum intensity projection. The largest intensity along the ray is
// classified once, at the end, so MIP needs neither gradient nor shading nor a lookup per sample.
#pragma once
#include "raycast_common.glsl"

void rcCompositeMip(inout RcState s, RcRay ray, float t, float intensity) {
    if (s.hitT < 0.0 || intensity > s.value) {
        s.value = intensity;
        s.hitT = t;  // the depth written is the maximum's
    }
}

// The maximum can come last: a MIP ray always runs to its exit.
bool rcTerminateMip(RcState s) { return false; }

vec4 rcFinishMip(RcState s) {
    vec4 color = RC_CLASSIFY(s.value);
    float alpha = clamp(color.a, 0.0, 1.0);
    return vec4(alpha * color.rgb, alpha);
}
