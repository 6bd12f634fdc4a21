// Lab 01, part 1: the classic diffuse + specular shader, the first thing to write in GLSL.
#pragma once
#include "gsv/not_done.glsl"

uniform float uShininess;     // the Phong exponent: larger is a smaller, sharper highlight
uniform float uSpecularStrength;  // strength of the white highlight

// TODO(L01-T2): the diffuse (Lambert) term. n and l are unit vectors in eye space.
// Light arriving from behind the surface (n.l < 0) adds nothing; keep a little ambient light
// (0.15 of k_d) so the unlit side is not pure black: k_d (0.15 + 0.85 max(n.l, 0)), never above k_d.
vec3 diffuse(vec3 n, vec3 l, vec3 kd) {
//@solution L01-T2
    const float ambient = 0.15;
    return kd * (ambient + (1.0 - ambient) * max(dot(n, l), 0.0));
//@starter
//    return kNotDone;
//@end
}

// TODO(L01-T3): the specular (Phong) term: reflect the light direction about the normal and raise
// its agreement with the view direction to the power uShininess. Every vector must be in the same
// space (eye space here). No highlight where the light is behind the surface.
vec3 specular(vec3 n, vec3 l, vec3 v) {
//@solution L01-T3
    if (dot(n, l) <= 0.0) return vec3(0.0);
    vec3 r = reflect(-l, n);
    return vec3(uSpecularStrength * pow(max(dot(r, v), 0.0), uShininess));
//@starter
//    return kNotDone;
//@end
}
