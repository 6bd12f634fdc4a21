// Lab 06: the same skeleton and modules as raycast.frag, but every module compiled in and chosen at run
// time by uniforms: the uber-shader the lab's measurement sets against the specialised one. For the same
// choices it computes the same image; gsv::raycast_uber_uniforms gives the uniforms for a configuration.
// It has every module's samplers, uGradientVolume and uTransferFunction included: set each to a unit of
// its own even when its module is off (see raycast_skeleton.glsl).
#include "raycast_common.glsl"
#include "gradient_forward.glsl"
#include "gradient_central.glsl"
#include "gradient_precomputed.glsl"
#include "classify_raw.glsl"
#include "classify_tf.glsl"
#include "shade_phong.glsl"

// The values are the order of gsv::RaycastConfig's enumerators.
uniform int uGradientMode;        // 0 none, 1 forward, 2 central, 3 precomputed
uniform int uClassificationMode;  // 0 raw, 1 transfer function
uniform int uShadingMode;         // 0 none, 1 Phong
uniform int uCompositingMode;     // 0 DVR, 1 MIP, 2 isosurface, 3 first hit
uniform int uEarlyTermination;    // DVR: 0 runs every ray to its exit

vec3 rcGradientUber(vec3 p) {
    if (uGradientMode == 1) return rcGradientForward(p);
    if (uGradientMode == 2) return rcGradientCentral(p);
    if (uGradientMode == 3) return rcGradientPrecomputed(p);
    return vec3(0.0);
}

vec4 rcClassifyUber(float intensity) {
    if (uClassificationMode == 1) return rcClassifyTf(intensity);
    return rcClassifyRaw(intensity);
}

vec3 rcShadeUber(vec3 color, vec3 gradient, vec3 p) {
    if (uShadingMode == 1) return rcShadePhong(color, gradient, p);
    return color;
}

#define RC_GRADIENT(p) rcGradientUber(p)
#define RC_CLASSIFY(intensity) rcClassifyUber(intensity)
#define RC_SHADE(color, gradient, p) rcShadeUber(color, gradient, p)

#include "composite_dvr.glsl"
#include "composite_mip.glsl"
#include "composite_iso.glsl"
#include "composite_fhp.glsl"

RcState rcStartUber(RcRay ray) {
    if (uCompositingMode == 0) return rcStartDvr(ray);
    if (uCompositingMode == 1) return rcStartMip(ray);
    if (uCompositingMode == 2) return rcStartIso(ray);
    return rcStartFhp(ray);
}

void rcCompositeUber(inout RcState s, RcRay ray, float t, float intensity) {
    if (uCompositingMode == 0) rcCompositeDvr(s, ray, t, intensity);
    else if (uCompositingMode == 1) rcCompositeMip(s, ray, t, intensity);
    else if (uCompositingMode == 2) rcCompositeIso(s, ray, t, intensity);
    else rcCompositeFhp(s, ray, t, intensity);
}

bool rcTerminateUber(RcState s) {
    if (uCompositingMode == 0) return uEarlyTermination != 0 && rcTerminateDvr(s);
    if (uCompositingMode == 1) return rcTerminateMip(s);
    if (uCompositingMode == 2) return rcTerminateIso(s);
    return rcTerminateFhp(s);
}

vec4 rcFinishUber(RcState s) {
    if (uCompositingMode == 0) return rcFinishDvr(s);
    if (uCompositingMode == 1) return rcFinishMip(s);
    if (uCompositingMode == 2) return rcFinishIso(s);
    return rcFinishFhp(s);
}

#define RC_START(ray) rcStartUber(ray)
#define RC_COMPOSITE(state, ray, t, intensity) rcCompositeUber(state, ray, t, intensity)
#define RC_TERMINATE(state) rcTerminateUber(state)
#define RC_FINISH(state) rcFinishUber(state)

#include "raycast_skeleton.glsl"
