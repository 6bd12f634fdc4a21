// Lab 06: the same skeleton and modules as raycast.frag, but every module compiled in and chosen at run
// time by uniforms: the uber-shader the lab's measurement sets against the specialised one. For the same
// choices it computes the same image; gsv::raycast_uber_uniforms gives the uniforms for a configuration.
// It has every module's samplers, uGradientVolume and uTransferFunction included: set each to a unit of
// its own even when its module is off (see raycast_skeleton.glsl).
#include "raycast_common.glsl"
// Generated from the module tables (gsv::generate_raycast_uber_header): every module's file, the mode uniforms and
// the RC_* placeholders as functions that branch on them, a branch a module.
#include "rc_uber.glsl"
#include "raycast_skeleton.glsl"
