// Lab 06, compositing module: direct volume rendering, front to back. Calls the RC_CLASSIFY, RC_GRADIENT
// and RC_SHADE placeholders, which must be defined before this file is included.
#pragma once
#include "gsv/not_done.glsl"
#include "raycast_common.glsl"

// The segment length the transfer function's opacities are meant for. A sample stands for a segment of
// ray.step; its opacity is corrected to alpha' = 1 - (1 - alpha)^(step / reference), so the image does
// not darken as the step shrinks. Equal to the step: no correction.
uniform float uReferenceStepSize;
// Stop once the accumulated opacity reaches this: what lies behind adds at most 1 - threshold. 1 keeps
// every ray going to its exit, and so does 0 (unset), which would otherwise stop every ray at once.
uniform float uEarlyRayThreshold;

// Every sample of a ray stands for the same ray.step: its opacity exponent is worked out once, here, and
// carried in s.value (per sample it cost the assembled ray caster against the hand-written one).
RcState rcStartDvr(RcRay ray) {
    RcState s = rcStartState();
    // TODO(L06-T3): the opacity correction's exponent for this ray, ray.step / uReferenceStepSize, kept in
    // s.value for rcCompositeDvr; with no correction (1) when the reference is 0.
//@solution L06-T3
    // Unset (0) reference: no correction rather than an infinite exponent.
    float exponent = uReferenceStepSize > 0.0 ? ray.step / uReferenceStepSize : 1.0;
    s.value = exponent;
//@starter
//    s.value = 1.0;
//@end
    return s;
}

void rcCompositeDvr(inout RcState s, RcRay ray, float t, float intensity) {
    // TODO(L06-T3): classify the sample; skip it if transparent; shade it (RC_SHADE with RC_GRADIENT at
    // its position); correct its opacity for the step, alpha' = 1 - (1 - alpha)^exponent with the
    // exponent rcStartDvr kept in s.value; remember the first visible sample's t in s.hitT; and blend it
    // front to back under what the ray has gathered (premultiplied).
//@solution L06-T3
    vec4 color = RC_CLASSIFY(intensity);
    // A transparent sample adds nothing: skip its gradient and shading (empty space is most samples).
    if (color.a <= 0.0) return;
    vec3 p = rcPosition(ray, t);
    color.rgb = RC_SHADE(color.rgb, RC_GRADIENT(p), p);
    float alpha = 1.0 - pow(1.0 - min(color.a, 1.0), s.value);
    if (s.hitT < 0.0) s.hitT = t;
    s.color += (1.0 - s.color.a) * vec4(alpha * color.rgb, alpha);
//@starter
//    s.color = vec4(kNotDone, 1.0);
//    if (s.hitT < 0.0) s.hitT = t;
//@end
}

bool rcTerminateDvr(RcState s) {
    // TODO(L06-T3): early ray termination: stop once the ray is uEarlyRayThreshold opaque (0: never).
//@solution L06-T3
    return uEarlyRayThreshold > 0.0 && s.color.a >= uEarlyRayThreshold;
//@starter
//    return false;
//@end
}

vec4 rcFinishDvr(RcState s) { return s.color; }
