// Particle scenes, their fields, and the initial particles.
#include "support/particles/particle_motion.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"
#include "common/core/splitmix64.h"

#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {
namespace {

// U[lo, hi) from draw `index` of the stream keyed by `seed`.
double uniform(std::uint64_t seed, std::uint64_t index, double lo, double hi) {
    return lo + (hi - lo) * unit_double(hash64(seed, index));
}

}  // namespace

ParticleScene particle_scene_from_name(const std::string& name) { return parse_enum(kParticleSceneNames, "particle scene", name); }
const char* particle_scene_name(ParticleScene scene) { return name_of(kParticleSceneNames, scene); }
Integrator integrator_from_name(const std::string& name) { return parse_enum(kIntegratorNames, "integrator", name); }
const char* integrator_name(Integrator integrator) { return name_of(kIntegratorNames, integrator); }

template <class T>
glm::tvec3<T> field_velocity(ParticleScene scene, glm::tvec3<T> p) {
    switch (scene) {
        case ParticleScene::Rotation: return {-p.y, p.x, T(0)};
        case ParticleScene::Saddle: return {p.x, -p.y, T(0)};
        case ParticleScene::Abc: {
            // T-typed constants: in float every operation rounds to float, as in the shader.
            const T pi = T(3.14159265358979323846);
            const T a = T(1.7320508075688772935), b = T(1.4142135623730950488), c = T(1);
            const glm::tvec3<T> q = pi * p;
            return glm::tvec3<T>(a * std::sin(q.z) + c * std::cos(q.y), b * std::sin(q.x) + a * std::cos(q.z),
                                 c * std::sin(q.y) + b * std::cos(q.x)) /
                   pi;
        }
        case ParticleScene::Gravity: break;
    }
    throw Error(std::string("field_velocity: the ") + particle_scene_name(scene) +
                " scene has no velocity field (its particles carry their own velocity)");
}

template glm::tvec3<float> field_velocity<float>(ParticleScene, glm::tvec3<float>);
template glm::tvec3<double> field_velocity<double>(ParticleScene, glm::tvec3<double>);

ParticleSet make_particles(ParticleScene scene, std::size_t count, std::uint64_t seed, double gravity) {
    if (!std::isfinite(gravity))
        throw Error("make_particles: gravity = " + std::to_string(gravity) + " must be finite");
    ParticleSet set;
    set.positions.resize(count);
    set.velocities.resize(count);
    set.origins.resize(count);
    if (gravity < 0) throw Error("make_particles: gravity = " + std::to_string(gravity) + " must not be negative");
    // Seven draws per particle whatever the scene, so particle i's draws are 7i .. 7i+6 in every scene.
    constexpr std::uint64_t kDraws = 7;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint64_t d = kDraws * i;
        glm::vec3 p0, v0;
        if (scene == ParticleScene::Gravity) {
            p0 = glm::vec3(glm::dvec3(uniform(seed, d, -0.05, 0.05), -0.8 + uniform(seed, d + 1, -0.05, 0.05),
                                      uniform(seed, d + 2, -0.05, 0.05)));
            v0 = glm::vec3(glm::dvec3(uniform(seed, d + 3, -0.35, 0.35), uniform(seed, d + 4, 1.6, 2.4),
                                      uniform(seed, d + 5, -0.35, 0.35)));
        } else {
            p0 = glm::vec3(
                glm::dvec3(uniform(seed, d, -1, 1), uniform(seed, d + 1, -1, 1), uniform(seed, d + 2, -1, 1)));
            // At the stored position, so that v0 is the field where the particle really starts.
            v0 = glm::vec3(field_velocity<double>(scene, glm::dvec3(p0)));
        }
        set.origins[i] = {glm::vec4(p0, 1.0f), glm::vec4(v0, 0.0f)};
        glm::dvec3 p(p0), v(v0);
        if (scene == ParticleScene::Gravity) {
            const double flight = gravity > 0 ? 2.0 * v.y / gravity : (1.0 - p.y) / v.y;
            const double tau = uniform(seed, d + 6, 0.0, flight);
            const glm::dvec3 g(0.0, -gravity, 0.0);
            const glm::dvec3 along = p + tau * v + (tau * tau / 2.0) * g;
            if (std::abs(along.x) <= 1 && std::abs(along.y) <= 1 && std::abs(along.z) <= 1) {
                p = along;
                v = v + tau * g;
            }
        }
        set.positions[i] = glm::vec4(glm::vec3(p), 1.0f);
        set.velocities[i] = glm::vec4(glm::vec3(v), 0.0f);
    }
    return set;
}

ParticleSet pad_particles(ParticleSet set, std::size_t capacity) {
    const std::size_t count = set.count();
    if (set.velocities.size() != count || set.origins.size() != count)
        throw Error("pad_particles: " + std::to_string(count) + " positions but " +
                    std::to_string(set.velocities.size()) + " velocities and " + std::to_string(set.origins.size()) +
                    " origins");
    if (capacity < count)
        throw Error("pad_particles: capacity " + std::to_string(capacity) + " is below the particle count " +
                    std::to_string(count));
    const glm::vec4 still(0.0f);
    set.positions.resize(capacity, kSentinelPosition);
    set.velocities.resize(capacity, still);
    set.origins.resize(capacity, ParticleOrigin{kSentinelPosition, still});
    return set;
}

}  // namespace gsv
