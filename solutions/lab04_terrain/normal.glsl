// Lab 04: the terrain's normal from its height texture, by finite differences (Bailey's bump-mapped
// terrain). World axes: x east, y up, z SOUTH, so the map reads north-up from above.
#pragma once

uniform sampler2D uHeights;  // metres, float; row 0 is the south row
uniform vec2 uSpacing;       // ground metres between neighbouring samples: east, north
uniform float uExaggeration; // vertical exaggeration
uniform float uDelta;        // finite-difference step in samples: the accuracy knob

uniform int uMipLevel;       // with mipmaps: -1 lets the hardware pick a level, k >= 0 reads level k

// The height at fractional sample index (i, j), i east and j north, each sample at its texel centre.
float heightAt(vec2 sampleIndex) {
    vec2 st = (sampleIndex + 0.5) / vec2(textureSize(uHeights, 0));
#ifdef EFFECT_MIPMAPS
    if (uMipLevel >= 0) return textureLod(uHeights, st, float(uMipLevel)).r;
#endif
    return texture(uHeights, st).r;
}

// The slope (dh/dx east, dh/dy north), metres per metre, at texture coordinate st.
vec2 terrainSlope(vec2 st) {
    vec2 size = vec2(textureSize(uHeights, 0));
    vec2 here = clamp(st * size - 0.5, vec2(0.0), size - 1.0);
    // TODO(L04-T1): differences uDelta samples each way, divided by the GROUND distance between the two
    // samples (uSpacing is metres per sample). Near a border one neighbour is missing: difference over the
    // samples that exist and divide by their own distance (one-sided), never by the full span, which
    // would halve the slope along every border. A grid one sample wide has no slope that way: 0, not 0/0.
//@solution L04-T1
    vec2 lo = max(here - uDelta, vec2(0.0));
    vec2 hi = min(here + uDelta, size - 1.0);
    vec2 span = (hi - lo) * uSpacing;
    float riseX = heightAt(vec2(hi.x, here.y)) - heightAt(vec2(lo.x, here.y));
    float riseY = heightAt(vec2(here.x, hi.y)) - heightAt(vec2(here.x, lo.y));
    return vec2(span.x > 0.0 ? riseX / span.x : 0.0, span.y > 0.0 ? riseY / span.y : 0.0);
//@starter
//    return vec2(0.0);
//@end
}

// The upward unit normal of y = uExaggeration * h.
vec3 terrainNormal(vec2 st) {
    // TODO(L04-T2): the tangents east (1, e dh/dx, 0) and north (0, e dh/dy, -1) (north is -z), and
    // their cross product, which points up. Its y is 1 before normalising, so its length is never 0.
//@solution L04-T2
    vec2 slope = uExaggeration * terrainSlope(st);
    return normalize(vec3(-slope.x, 1.0, slope.y));
//@starter
//    return vec3(0.0, 1.0, 0.0);
//@end
}
