// Lab 05: the velocity field u(p) on the domain [-1,1]^3, in domain lengths per unit time. The same fields
// in C++ (support/particles/particle_motion.cpp) give the double-precision reference. Only the chosen field is compiled.
#pragma once

const float kPi = 3.14159265358979323846;

#if defined(SOURCE_TEXTURE)
// The field sampled at texel centres over the domain (support/particles/particle_grid.cpp), filtered linearly and
// clamped at the edges: the seed's Figure 9, where the velocities come from data, not a formula.
uniform sampler3D uVelocityTexture;
#endif

vec3 velocity(vec3 p) {
#if defined(SOURCE_TEXTURE)
    // TODO(L05-T5): look the velocity up in uVelocityTexture. Texture coordinates run over [0,1]; the
    // domain over [-1,1].
    return vec3(0.0);
#elif defined(FIELD_ROTATION)
    return vec3(-p.y, p.x, 0.0);  // circles about the z axis, one turn in 2 pi; still at the centre
#elif defined(FIELD_SADDLE)
    return vec3(p.x, -p.y, 0.0);  // in along y, out along x; still at the centre
#elif defined(FIELD_ABC)
    // The Arnold-Beltrami-Childress flow over one period, scaled to the domain.
    const float A = sqrt(3.0), B = sqrt(2.0), C = 1.0;
    vec3 q = kPi * p;
    return vec3(A * sin(q.z) + C * cos(q.y), B * sin(q.x) + A * cos(q.z), C * sin(q.y) + B * cos(q.x)) / kPi;
#else
    return vec3(0.0);  // gravity moves particles by their own velocity (integrate.glsl)
#endif
}
