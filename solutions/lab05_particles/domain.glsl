// Lab 05: the domain [-1,1]^3 and what happens to a particle that leaves it. One function for both steps: the compute
// shader's (advect.comp) and, where there are no compute shaders (WebGL 2, OpenGL ES 3.0), transform feedback's
// (advect_captured.vert).
#pragma once

// p and v: the particle after its step; startPosition and startVelocity: where it started, and how fast.
void returnIfOutside(inout vec3 p, inout vec3 v, vec3 startPosition, vec3 startVelocity) {
    // TODO(L05-T3): a particle that left the domain [-1,1]^3 (any coordinate beyond 1 in size; on the
    // boundary is still inside) goes back to where it started, with the velocity it started with.
//@solution L05-T3
    if (any(greaterThan(abs(p), vec3(1.0)))) {
        p = startPosition;
        v = startVelocity;
    }
//@starter
//@end
}
