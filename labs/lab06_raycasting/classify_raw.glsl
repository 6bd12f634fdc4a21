// Lab 06, classification module: the intensity itself is the opacity of white matter, so DVR shows the
// volume's density as grey and MIP the largest intensity as its grey level. No lookup.
#pragma once

vec4 rcClassifyRaw(float intensity) {
    return vec4(1.0, 1.0, 1.0, clamp(intensity, 0.0, 1.0));
}
