// Lab 01 measurement pass (not a student file): the angle between the normal the shader lights with
// (interpolated, renormalized) and the exact normal of the unit sphere, in degrees, in the red channel
// of a float target. The sweep averages it over the covered pixels.
#include "gsv/math.glsl"

in vec3 vEyePosition;
in vec3 vEyeNormal;
in vec3 vObjectPosition;

out vec4 fColor;

void main() {
    vec3 used = safe_normalize(vEyeNormal, vec3(0.0, 0.0, 1.0));
    vec3 exact = safe_normalize(uNormalMatrix * vObjectPosition, vec3(0.0, 0.0, 1.0));
    fColor = vec4(degrees(angle_between(used, exact)), 0.0, 0.0, 1.0);
}
