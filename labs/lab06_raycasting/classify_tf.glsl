// Lab 06, classification module: a 1D transfer function, intensity -> colour and opacity.
#pragma once

// RGBA, one row (height 1: the kit's textures are 2D or 3D); straight colour, not premultiplied. Linear
// filtering and clamp to edge: intensity 0 reads the first entry, 1 the last, and between entries blends.
uniform sampler2D uTransferFunction;

vec4 rcClassifyTf(float intensity) {
    return texture(uTransferFunction, vec2(intensity, 0.5));
}
