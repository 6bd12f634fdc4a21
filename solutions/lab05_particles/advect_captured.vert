// Lab 05 where there are no compute shaders (WebGL 2, OpenGL ES 3.0): the same time step as advect.comp, one vertex a
// particle, its results captured into buffers by transform feedback instead of written into storage buffers. The
// step itself is yours, from the same files: integrate.glsl, domain.glsl and speed_color.glsl. What has no
// counterpart here is advect.comp's own (L05-T2): there are no work groups to lay out.
#include "integrate.glsl"
#include "domain.glsl"
#include "speed_color.glsl"

// particle_buffers.h: the step's attribute slots; the position is the kit's aVertex.
layout(location = 4) in vec4 aVelocity;
layout(location = 5) in vec4 aStartPosition;
layout(location = 6) in vec4 aStartVelocity;
layout(location = 3) in vec4 aColor;  // kColorSlot, as particles.vert

uniform float uTimeStep;  // h, the accuracy knob; 0 recolours without moving

out vec4 tfPosition;
out vec4 tfVelocity;
out vec4 tfColor;

void main() {
    vec3 p = aVertex.xyz;
    vec3 v = aVelocity.xyz;
    advance(p, v, uTimeStep);
    returnIfOutside(p, v, aStartPosition.xyz, aStartVelocity.xyz);
    tfPosition = vec4(p, aVertex.w);
    tfVelocity = vec4(v, aVelocity.w);
#ifdef EFFECT_COLOR_BY_SPEED
    tfColor = vec4(speedColor(length(v)), 1.0);
#else
    tfColor = aColor;  // as advect.comp, which writes no colours then
#endif
}
