// Lab 04 vertex stage: the terrain's grid (one quad for bump mapping, N x N vertices for real geometry)
// over the unit square, placed in the world: x east, z south, y up.
#include "normal.glsl"

uniform vec2 uGround;      // the terrain's extent east and north, in model units
uniform float uMidHeight;  // metres: the height drawn at y = 0
uniform float uUnitsPerMetre;

out vec2 vTexCoord;

void main() {
    vec2 st = aVertex.xz;
    float h = uMidHeight;
#ifdef GEOMETRY_MESH
    // TODO(L04-T4): real geometry: each vertex at the height of the terrain under it.
//@solution L04-T4
    h = heightAt(st * vec2(textureSize(uHeights, 0)) - 0.5);
//@starter
//@end
#endif
    vec3 p = vec3((st.x - 0.5) * uGround.x, uExaggeration * (h - uMidHeight) * uUnitsPerMetre, (0.5 - st.y) * uGround.y);
    vTexCoord = st;
    gl_Position = uModelViewProjectionMatrix * vec4(p, 1.0);
}
