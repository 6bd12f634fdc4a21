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
    return kNotDone;
}
