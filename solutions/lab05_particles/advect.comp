// Lab 05: one time step for every particle, straight in the storage buffers (Bailey, "Using GPU Shaders
// for Visualization, Part 3": Figure 6 under gravity, Figure 8 through a formula, Figure 9 through a 3D
// texture).
#include "particles.glsl"
#include "integrate.glsl"
#include "domain.glsl"
#include "speed_color.glsl"

layout(local_size_x = LOCAL_SIZE) in;

uniform int uCount;       // particles; the buffers have more slots, holding sentinels
uniform float uTimeStep;  // h, the accuracy knob; 0 recolours without moving

void main() {
    // TODO(L05-T2): which particle is this invocation's? The C++ lays the work groups out in rows
    // (common/gl/compute.h) when there are more than one row may hold, so count the rows above this one too.
    // The last groups run past the particle count: those invocations must touch nothing.
//@solution L05-T2
    uint index = gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x + gl_GlobalInvocationID.x;
    if (index >= uint(uCount)) return;
//@starter
//    uint index = gl_GlobalInvocationID.x;
//@end
    vec3 p = positions[index].xyz;
    vec3 v = velocities[index].xyz;
    advance(p, v, uTimeStep);
    returnIfOutside(p, v, origins[index].position.xyz, origins[index].velocity.xyz);
    positions[index].xyz = p;
    velocities[index].xyz = v;
#ifdef EFFECT_COLOR_BY_SPEED
    colors[index] = vec4(speedColor(length(v)), 1.0);
#endif
}
