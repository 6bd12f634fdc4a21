// Lab 06, shading module: Phong's ambient + diffuse + specular with the normal taken from the gradient.
#pragma once
#include "gsv/math.glsl"
#include "gsv/not_done.glsl"
#include "volume_geometry.glsl"

uniform vec3 uLightPosition;   // in volume texture coordinates (outside [0, 1]^3 is fine)
uniform vec3 uCameraPosition;  // in volume texture coordinates
uniform float uAmbient;        // k_a
uniform float uDiffuse;        // k_d
uniform float uSpecular;       // k_s of a white highlight
uniform float uShininess;      // the Phong exponent

// color: the classified colour (straight); gradient: in physical units; p: the sample's position.
vec3 rcShadePhong(vec3 color, vec3 gradient, vec3 p) {
    // TODO(L06-T2): Phong: ambient + diffuse times the colour, plus a white highlight. The normal is the
    // gradient reversed and normalised; where the gradient is 0 (a constant region) keep only the ambient
    // term, never NaN. Measure angles in physical units (rcPhysicalScale()), and light the side that
    // faces the camera.
//@solution L06-T2
    // The normal points down the gradient, out of the denser material. A constant region has no
    // gradient: a zero normal, so only ambient light, where normalize() would give NaN.
    vec3 n = -safeNormalize(gradient, vec3(0.0));
    // Directions in physical units, like the gradient: on an anisotropic grid, texture space bends angles.
    vec3 scale = rcPhysicalScale();
    vec3 l = safeNormalize((uLightPosition - p) * scale, vec3(0.0));
    vec3 v = safeNormalize((uCameraPosition - p) * scale, vec3(0.0));
    // Inside a volume a boundary is seen from either side: light the side that faces the camera.
    if (dot(n, v) < 0.0) n = -n;
    float diffuse = max(dot(n, l), 0.0);
    float rv = max(dot(reflect(-l, n), v), 0.0);
    // pow(0, e) is undefined for e <= 0: no highlight without light or without a reflection to see.
    float specular = diffuse > 0.0 && rv > 0.0 ? pow(rv, max(uShininess, 0.0)) : 0.0;
    return color * (uAmbient + uDiffuse * diffuse) + vec3(uSpecular * specular);
//@starter
//    return kNotDone;
//@end
}
