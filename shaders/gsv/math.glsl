// Small numerical guards every lab needs.
#pragma once

// normalize() of a zero vector is NaN, and NaN spreads through every later operation; below a
// tiny length there is no direction to keep, so fall back to one the caller chooses.
vec3 safeNormalize(vec3 v, vec3 fallback) {
    float lengthSquared = dot(v, v);
    return lengthSquared > 1e-20 ? v * inversesqrt(lengthSquared) : fallback;
}

vec2 safeNormalize(vec2 v, vec2 fallback) {
    float lengthSquared = dot(v, v);
    return lengthSquared > 1e-20 ? v * inversesqrt(lengthSquared) : fallback;
}

// The angle between two directions in radians, accurate for tiny angles where acos(dot) loses
// every digit (acos is flat near 1: an angle of 1e-4 rad moves the dot product by 5e-9).
float angleBetween(vec3 a, vec3 b) {
    return atan(length(cross(a, b)), dot(a, b));
}
