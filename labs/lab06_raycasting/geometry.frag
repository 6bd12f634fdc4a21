// Lab 06: the probe's own colour, lit by a light at the eye (Blinn-Phong in view space).
#include "gsv/math.glsl"

in vec3 vViewNormal;
in vec3 vViewPosition;
out vec4 fColor;

uniform vec3 uGeometryColor;

void main() {
    vec3 n = safeNormalize(vViewNormal, vec3(0.0, 0.0, 1.0));
    vec3 v = safeNormalize(-vViewPosition, vec3(0.0, 0.0, 1.0));
    if (dot(n, v) < 0.0) n = -n;
    float diffuse = max(dot(n, v), 0.0);
    float specular = pow(max(dot(n, v), 0.0), 48.0);
    fColor = vec4(uGeometryColor * (0.25 + 0.75 * diffuse) + vec3(0.35 * specular), 1.0);
}
