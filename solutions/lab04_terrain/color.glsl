// Lab 04: colour by height, after Bailey's Figure 6c: sea, green, brown and snow.
#pragma once
#include "gsv/not_done.glsl"

uniform vec2 uHeightRange;  // the terrain's lowest and highest heights, metres
uniform float uTreeLine;    // where green turns brown, as a fraction of the land's height range
uniform float uSnowLine;    // where brown turns to snow
uniform float uBlend;       // half the width of each transition, in the same fraction

const vec3 kSea = vec3(0.16, 0.32, 0.62);
const vec3 kGreen = vec3(0.26, 0.50, 0.21);
const vec3 kBrown = vec3(0.52, 0.39, 0.25);
const vec3 kSnow = vec3(0.95, 0.95, 0.97);
const vec3 kPlain = vec3(0.75, 0.72, 0.68);

vec3 heightColor(float h) {
#ifdef COLORING_PLAIN
    return kPlain;
#else
    if (h < 0.0) return kSea;
    float land = max(uHeightRange.x, 0.0);
    float f = (h - land) / max(uHeightRange.y - land, 1e-6);
    // TODO(L04-T3): green below the tree line, brown above it, snow above the snow line; blend each
    // border with smoothstep over +-uBlend, so the colours change smoothly instead of in hard contours.
//@solution L04-T3
    vec3 color = mix(kGreen, kBrown, smoothstep(uTreeLine - uBlend, uTreeLine + uBlend, f));
    return mix(color, kSnow, smoothstep(uSnowLine - uBlend, uSnowLine + uBlend, f));
//@starter
//    return kNotDone;
//@end
#endif
}
