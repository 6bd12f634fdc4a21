// Lab 05: one time step h of one particle. The integrator is chosen when the shader is compiled, so a
// step costs exactly its own velocity lookups: 1 for Euler, 2 for the midpoint rule, 4 for RK4.
#pragma once
#include "velocity.glsl"

uniform float uGravity;

// p and v: the particle's position and velocity. The fields' particles have no velocity of their own:
// v comes back as the velocity where the step began, which colours them.
void advance(inout vec3 p, inout vec3 v, float h) {
#if defined(FIELD_GRAVITY)
    vec3 g = vec3(0.0, -uGravity, 0.0);
#if defined(INTEGRATOR_EULER)
    // TODO(L05-T3): Euler's step under gravity: position by the velocity, velocity by gravity, both over h,
    // both from the values at the start of the step.
#else
    // TODO(L05-T4): the midpoint rule under gravity. With a constant acceleration it is exact, and it is
    // the seed's update (Figure 6): the position gains h v plus half of h squared times g.
#endif
#else
    vec3 k1 = velocity(p);
    v = k1;
#if defined(INTEGRATOR_EULER)
    // TODO(L05-T3): Euler's step: along the velocity at p for the whole of h.
#elif defined(INTEGRATOR_MIDPOINT)
    // TODO(L05-T4): the midpoint rule: half a step along k1, then the whole step along the velocity there.
#else
    // TODO(L05-T4): classic fourth-order Runge-Kutta: k2 and k3 at half steps, k4 at a whole step, then
    // the weighted mean (k1 + 2 k2 + 2 k3 + k4) / 6.
#endif
#endif
}
