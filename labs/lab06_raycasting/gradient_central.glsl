// Lab 06, gradient module: central differences, (v(x + h) - v(x - h)) / (2 spacing) per axis.
// Six lookups; second-order accurate.
#pragma once
#include "volume_geometry.glsl"

vec3 rcGradientCentral(vec3 p) {
    // TODO(L06-T1): the gradient at p by central differences one voxel (rcVoxelStep()) either side along
    // each axis, divided by the physical distance between the two lookups (rcVoxelSpacing() per voxel),
    // as the forward-difference module does one-sided. Until then: no gradient, so no shading.
    return vec3(0.0);
}
