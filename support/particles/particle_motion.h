#pragma once
// Lab 05's particles on the CPU: the scenes, their velocity fields and the initial particles the lab uploads.
// How a particle moves (the integrators, the lab's TODOs) is not here: the instructor's CPU yardstick of them
// is in reference/particles/particle_step.h, which neither the student edition nor a student's build sees.
//
// The domain is D = [-1,1]^3. A particle that leaves it starts over at its origin, so a finite buffer shows a
// steady stream instead of emptying.
#include "common/core/enum_names.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gsv {

// A particle's starting state, to which it returns when it leaves the domain. Two vec4s, 32 bytes, the
// layout of the GLSL struct { vec4 position; vec4 velocity; } in a std430 buffer.
struct ParticleOrigin {
    glm::vec4 position;  // w = 1
    glm::vec4 velocity;  // w = 0
};
static_assert(sizeof(ParticleOrigin) == 32, "ParticleOrigin must match the shader's std430 struct");

// The particles as the GPU buffers hold them: one vec4 per particle in each array. Positions have w = 1 and
// velocities w = 0, except padding sentinels (pad_particles), whose position w = 0 marks them as not drawn.
struct ParticleSet {
    std::vector<glm::vec4> positions, velocities;
    std::vector<ParticleOrigin> origins;

    std::size_t count() const { return positions.size(); }
};

// Rotation, Saddle and Abc move particles along a velocity field u(p); Gravity has no field: each particle
// carries its own velocity and a constant acceleration changes it (a fountain).
enum class ParticleScene { Gravity, Rotation, Saddle, Abc };
enum class Integrator { Euler, Midpoint, Rk4 };
inline constexpr ParticleScene kParticleScenes[] = {ParticleScene::Gravity, ParticleScene::Rotation,
                                                    ParticleScene::Saddle, ParticleScene::Abc};
inline constexpr Integrator kIntegrators[] = {Integrator::Euler, Integrator::Midpoint, Integrator::Rk4};
inline constexpr EnumName<ParticleScene> kParticleSceneNames[] = {{ParticleScene::Gravity, "gravity"},
                                                                  {ParticleScene::Rotation, "rotation"},
                                                                  {ParticleScene::Saddle, "saddle"},
                                                                  {ParticleScene::Abc, "abc"}};
inline constexpr EnumName<Integrator> kIntegratorNames[] = {
    {Integrator::Euler, "euler"}, {Integrator::Midpoint, "midpoint"}, {Integrator::Rk4, "rk4"}};

// Names of those tables; any other name throws gsv::Error naming it and listing them.
ParticleScene particle_scene_from_name(const std::string& name);
const char* particle_scene_name(ParticleScene scene);
Integrator integrator_from_name(const std::string& name);
const char* integrator_name(Integrator integrator);

// The analytic field in domain units per unit time, for T = float or double (computed in T throughout, as
// the shader computes in float):
//   Rotation  u = (-y, x, 0)    circles about the z axis, period 2 pi; stagnation point at the origin
//   Saddle    u = (x, -y, 0)    in along y, out along x; stagnation point at the origin
//   Abc       the Arnold-Beltrami-Childress flow, one period across D: with X = pi p,
//             u = (A sin Z + C cos Y, B sin X + A cos Z, C sin Y + B cos X) / pi, A = sqrt 3, B = sqrt 2, C = 1
//             (a steady solution of Euler's equations whose streamlines are chaotic: small errors grow)
// Throws gsv::Error for Gravity, which has no field.
template <class T>
glm::tvec3<T> field_velocity(ParticleScene scene, glm::tvec3<T> p);

// The initial particles of a scene, the same for a seed on every machine (hash64 draws of splitmix64.h;
// particle i uses only its own draws, so a smaller count gives a prefix of a larger one):
//   field scenes  p0 uniform in [-1,1)^3, v0 = u(p0) evaluated in double at the stored (float) p0
//   Gravity       p0 = (0, -0.8, 0) + uniform [-0.05, 0.05) per axis,
//                 v0 = (U[-0.35, 0.35), U[1.6, 2.4), U[-0.35, 0.35)), whatever `gravity` is: the launch
//                 is fixed and G shapes the arcs (with G = 2 they top out between y = -0.16 and 0.64).
//                 A fountain that all left the nozzle at once would be one burst, not a fountain: each
//                 particle starts a time U[0, tau) into its flight along the exact parabola, tau the time
//                 it takes to fall back to the nozzle's height (2 v0y / G; with G = 0, the time to reach
//                 the ceiling), or at the nozzle if that point is outside the domain.
// positions = where the particle starts (w 1), velocities = its velocity there (w 0), origins = {p0, v0}:
// the same as the positions except in a fountain. gsv::Error when `gravity` is not finite or negative.
ParticleSet make_particles(ParticleScene scene, std::size_t count, std::uint64_t seed, double gravity = 2);

// The sentinel that fills the slots past the particle count: position and origin position (0.3, 0.6, 0.2, 0),
// velocity and origin velocity 0. w = 0 marks it (never drawn). A shader that forgets its bounds check moves
// it (every scene does: its field is not zero there, and gravity accelerates it), which a grader can see.
inline constexpr glm::vec4 kSentinelPosition{0.3f, 0.6f, 0.2f, 0.0f};

// `set` extended to `capacity` slots with sentinels (the GPU lab rounds its buffers up to a multiple of its
// work-group size). Throws gsv::Error when capacity is below set.count() or the set's arrays differ in size.
ParticleSet pad_particles(ParticleSet set, std::size_t capacity);

}  // namespace gsv
