// Lab 01 measurement pass (not a student file): the true sphere the mesh approximates, ray-cast at each
// pixel's centre and lit with its exact normal at the exact point: what the sweep measures both shading
// rates against. The same lighting functions as shade.frag, so only the geometry and the rate differ.
#include "lighting.glsl"

in vec2 vTexCoord;

uniform mat4 uInverseProjection;  // clip space back to eye space, for this pixel's eye ray

out vec4 fColor;

void main() {
    vec4 near = uInverseProjection * vec4(vTexCoord * 2.0 - 1.0, -1.0, 1.0);
    vec3 d = safeNormalize(near.xyz / near.w, vec3(0.0, 0.0, -1.0));
    // The model's sphere in eye space (the exact reference is drawn only for a uniform scale).
    vec3 centre = (uModelViewMatrix * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
    float radius = length(uModelViewMatrix[0].xyz);
    float b = dot(d, centre);
    float discriminant = b * b - dot(centre, centre) + radius * radius;
    if (discriminant < 0.0) discard;
    vec3 hit = (b - sqrt(discriminant)) * d;
    vec3 n = safeNormalize(hit - centre, vec3(0.0, 0.0, 1.0));
    fColor = vec4(shade(n, hit), 1.0);
}
