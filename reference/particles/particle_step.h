#pragma once
// Lab 05's integrators on the CPU, the instructor's yardstick of the compute shader (the lab's TODOs L05-T3 to
// L05-T5): one step of one particle, written once as a template so that the same lines run in double (the
// correctness reference) and in float (what the compute shader does, in the shader's order of operations, so a
// float CPU run and the GPU agree to a few ulps rather than only to the method's error). Moved out of support/
// so that no student's copy holds the answers: reference/ is linked by the solutions and the tests only.
//
// A particle that ends a step outside D = [-1,1]^3 (some |p_i| > 1, strictly) starts over at its origin.
#include "support/particles/particle_grid.h"
#include "support/particles/particle_motion.h"

#include <glm/glm.hpp>

namespace gsv {

// What one step of `integrator` does to a particle's distance from the axis of the rotation u = (-y, x, 0): the
// exact flow keeps it, a step multiplies it by |R(ih)|, R the method's stability polynomial (1 + z for Euler,
// 1 + z + z^2/2 for midpoint, up to z^4/24 for RK4). So n steps take a radius r to r |R(ih)|^n: after one turn
// at h = 0.1, 1.368 for Euler, 1.0008 for midpoint, 0.9999996 for RK4.
double rotation_radius_growth_per_step(Integrator integrator, double h);

// One step's settings. `grid`, when set, replaces the analytic field of a field scene by its trilinear
// lookup (the 3D texture the shader samples); it must outlive the steps. Gravity ignores it, and
// check_step_spec refuses the pair, since a grid there is surely a caller's mistake.
struct StepSpec {
    ParticleScene scene = ParticleScene::Rotation;
    Integrator integrator = Integrator::Rk4;
    double h = 0.01;     // the time step
    double gravity = 2;  // G of g = (0, -G, 0), Gravity only
    const VelocityGrid* grid = nullptr;
};

// Throws gsv::Error for a step h or gravity that is not finite, a scene or integrator outside the enums, a
// grid given with Gravity, or a grid whose side or texel count is not one VelocityGrid::sample makes.
// step_particle itself checks nothing (it runs per particle per step): callers check once, as advance_cpu
// and advance_reference do.
void check_step_spec(const StepSpec& spec);

// One step of one particle in T = float or double, h and G rounded to T first:
//   Gravity (p' = v, v' = g):
//     euler               p1 = p + h v;               v1 = v + h g
//     midpoint and rk4    p1 = p + h v + (h h / 2) g;  v1 = v + h g   (exact for constant acceleration)
//   field scenes (u = the analytic field, or spec.grid's lookup):
//     euler     k1 = u(p); p1 = p + h k1
//     midpoint  k1 = u(p); k2 = u(p + (h/2) k1); p1 = p + h k2
//     rk4       ... k3 = u(p + (h/2) k2); k4 = u(p + h k3); p1 = p + (h/6) (k1 + 2 k2 + 2 k3 + k4)
//     v1 = k1, the velocity where the step began (it colours the particle).
// Then, if some |p1_i| > 1, the particle returns to its origin: p1 = p0, v1 = v0; on the boundary it stays.
// Returns true when it returned. Defined for float and double only.
template <class T>
bool step_particle(const StepSpec& spec, glm::tvec3<T>& p, glm::tvec3<T>& v, const glm::tvec3<T>& p0,
                   const glm::tvec3<T>& v0);

}  // namespace gsv
