// Lab 06, gradient module: forward differences, (v(x + h) - v(x)) / spacing per axis, one voxel ahead.
// Three lookups besides the sample's own (which the compiler may share with the skeleton's); first-order
// accurate, so the gradient leans half a voxel forward. Matches gsv::forward_difference at step 1.
#pragma once
#include "volume_geometry.glsl"

vec3 rcGradientForward(vec3 p) {
    vec3 h = rcVoxelStep();
    float v = texture(uVolume, p).r;
    vec3 ahead = vec3(texture(uVolume, p + vec3(h.x, 0.0, 0.0)).r,
                      texture(uVolume, p + vec3(0.0, h.y, 0.0)).r,
                      texture(uVolume, p + vec3(0.0, 0.0, h.z)).r);
    return (ahead - v) / rcVoxelSpacing();
}
