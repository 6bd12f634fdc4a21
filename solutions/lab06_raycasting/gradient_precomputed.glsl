// Lab 06, gradient module: a gradient volume computed beforehand, one lookup per sample instead of six,
// paid for with three times the memory of the volume.
#pragma once
#include "raycast_common.glsl"

// The gradient itself in RGB (RGB32F, physical units): a 3x3x3 Sobel operator at every voxel
// (support/volume/sobel_gradient.h), smoother than the per-sample modules, as a volume computed once can afford.
// Not packed into [0, 1]: packing into 8 bits would quantise the directions the shading shows.
uniform sampler3D uGradientVolume;

vec3 rcGradientPrecomputed(vec3 p) { return texture(uGradientVolume, p).xyz; }
