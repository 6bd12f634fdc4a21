// A compositing mode added by a test (tests/test_raycast_shaders.cpp), to show that a new mode is this file and one
// row of lab 06's table: the mean intensity along the ray, classified once, drawn opaque. The depth is the first
// sample's.
#pragma once
#include "raycast_common.glsl"

RcState rcStartTestAvg(RcRay ray) { return rcStartState(); }

void rcCompositeTestAvg(inout RcState s, RcRay ray, float t, float intensity) {
    s.value += intensity / float(ray.samples);
    if (s.hitT < 0.0) s.hitT = t;
}

bool rcTerminateTestAvg(RcState s) { return false; }

vec4 rcFinishTestAvg(RcState s) { return vec4(RC_CLASSIFY(s.value).rgb, 1.0); }
