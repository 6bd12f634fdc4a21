// Lab 04 fragment stage: lights the terrain with the normal its heights give (normal.glsl) and colours it
// by height (color.glsl). With GEOMETRY_BUMP the surface is one flat quad: only the normal is real.
#include "gsv/not_done.glsl"
#include "normal.glsl"
#include "color.glsl"

uniform vec3 uLightDirection;  // towards the light, world space

in vec2 vTexCoord;
out vec4 fColor;

void main() {
#ifdef SHADING_SLOPES
    // The slope itself, before any normal or light: what L04-T1 computes, east-rising red and north-rising green
    // (times the exaggeration), both 0.5 where the ground is level.
    vec2 slope = uExaggeration * terrainSlope(vTexCoord);
    fColor = vec4(0.5 + 0.5 * clamp(slope, -1.0, 1.0), 0.5, 1.0);
#else
    vec3 n = terrainNormal(vTexCoord);
    float h = texture(uHeights, vTexCoord).r;
    float diffuse = max(dot(n, normalize(uLightDirection)), 0.0);
    fColor = vec4(heightColor(h) * (0.22 + 0.78 * diffuse), 1.0);
#endif
}
