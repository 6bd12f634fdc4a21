// Lab 01: the lighting model, shared by the vertex stage (per-vertex shading) and the fragment stage.
#pragma once
#include "gsv/math.glsl"
#include "phong.glsl"
#include "gooch.glsl"

uniform vec3 uLightEye;      // the light's position in eye space (lab.cpp transforms uLightPosition)
uniform vec3 uDiffuseColor;  // k_d, the surface's own colour

// n: unit normal in eye space, facing the side being shaded; eyePosition: the point in eye space.
vec3 shade(vec3 n, vec3 eyePosition) {
    // The light may sit on the surface itself: no direction then, so light it head-on.
    vec3 l = safeNormalize(uLightEye - eyePosition, n);
    // The eye is at the origin of eye space.
    vec3 v = safeNormalize(-eyePosition, n);
#ifdef SHADING_GOOCH
    vec3 color = gooch(n, l, uDiffuseColor);
#else
    vec3 color = diffuse(n, l, uDiffuseColor);
#endif
#ifdef EFFECT_SPECULAR
    color += specular(n, l, v);
#endif
    return color;
}
