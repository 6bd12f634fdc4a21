// Lab 06, gradient module: central differences, (v(x + h) - v(x - h)) / (2 spacing) per axis.
// Six lookups; second-order accurate.
#pragma once
#include "volume_geometry.glsl"

vec3 rcGradientCentral(vec3 p) {
    // TODO(L06-T1): the gradient at p by central differences one voxel (rcVoxelStep()) either side along
    // each axis, divided by the physical distance between the two lookups (rcVoxelSpacing() per voxel),
    // as the forward-difference module does one-sided. Until then: no gradient, so no shading.
//@solution L06-T1
    vec3 h = rcVoxelStep();
    vec3 ahead = vec3(texture(uVolume, p + vec3(h.x, 0.0, 0.0)).r,
                      texture(uVolume, p + vec3(0.0, h.y, 0.0)).r,
                      texture(uVolume, p + vec3(0.0, 0.0, h.z)).r);
    vec3 behind = vec3(texture(uVolume, p - vec3(h.x, 0.0, 0.0)).r,
                       texture(uVolume, p - vec3(0.0, h.y, 0.0)).r,
                       texture(uVolume, p - vec3(0.0, 0.0, h.z)).r);
    return (ahead - behind) / (2.0 * rcVoxelSpacing());
//@starter
//    return vec3(0.0);
//@end
}
