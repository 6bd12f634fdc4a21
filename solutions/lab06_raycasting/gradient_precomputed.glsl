// Lab 06, gradient module: a gradient volume computed beforehand, one lookup per sample instead of six,
// paid for with three times the memory of the volume.
#pragma once
#include "raycast_common.glsl"

// The gradient itself in RGB (RGB32F, physical units, e.g. gsv::central_difference at every voxel), not
// packed into [0, 1]: packing into 8 bits would quantise the directions the shading shows.
uniform sampler3D uGradientVolume;

vec3 rcGradientPrecomputed(vec3 p) { return texture(uGradientVolume, p).xyz; }
