// Lab 01 measurement pass (not a student file): the angle between the normal the shader lights with
// (interpolated, renormalized) and the exact normal of the sphere the mesh approximates, at the point
// where this pixel's eye ray meets that sphere, in degrees, in the red channel of a float target.
// (Not the sphere normal at the radial projection of the fragment: on a sphere mesh with exact vertex
// normals the renormalized interpolated normal IS that direction, which would hide the error.)
#include "gsv/math.glsl"

in vec3 vEyePosition;
in vec3 vEyeNormal;
in vec3 vObjectPosition;

out vec4 fColor;

void main() {
    // The model's sphere in eye space: centre and radius (the lab's sweep uses a uniform scale).
    vec3 centre = (uModelViewMatrix * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
    float radius = length(uModelViewMatrix[0].xyz);
    // The eye ray from the origin through this fragment, and its nearer hit with the true sphere.
    // The mesh lies inside its sphere, so every covered pixel's ray meets the sphere; max() guards
    // rounding at the silhouette.
    vec3 d = safeNormalize(vEyePosition, vec3(0.0, 0.0, -1.0));
    float b = dot(d, centre);
    float t = b - sqrt(max(b * b - dot(centre, centre) + radius * radius, 0.0));
    vec3 exact = safeNormalize(t * d - centre, vec3(0.0, 0.0, 1.0));
    vec3 used = safeNormalize(vEyeNormal, vec3(0.0, 0.0, 1.0));
    fColor = vec4(degrees(angleBetween(used, exact)), 0.0, 0.0, 1.0);
}
