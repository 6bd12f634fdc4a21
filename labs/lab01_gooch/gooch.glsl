// Lab 01, part 2: Gooch cool-to-warm shading (Gooch, Gooch, Shirley, Cohen 1998), the technical-
// illustration look: hue, not brightness, tells which way a surface faces the light.
#pragma once

uniform float uBlue;    // b: strength of the pure blue k_blue = (0, 0, b)
uniform float uYellow;  // y: strength of the pure yellow k_yellow = (y, y, 0)
uniform float uAlpha;   // how much of k_d the cool colour keeps
uniform float uBeta;    // how much of k_d the warm colour keeps

// TODO(L01-T4): k_cool = k_blue + alpha k_d and k_warm = k_yellow + beta k_d, blended by
// t = (1 + n.l) / 2 so that the side facing the light (n.l = 1) is WARM and the side facing away is
// cool. (Careful: the formula as often quoted weights k_cool by t, which puts cool towards the light.)
vec3 gooch(vec3 n, vec3 l, vec3 kd) {
    return kNotDone;
}
