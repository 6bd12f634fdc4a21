// Particle scenes, fields and integrators, one step at a time, in float and in double.
#include "support/particles/particle_motion.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"
#include "common/core/splitmix64.h"
#include "support/particles/particle_grid.h"

#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {
namespace {

// The field where the integrator asks for it: the grid's lookup when there is one (what the shader's
// texture() returns), else the formula.
template <class T>
glm::tvec3<T> velocity_at(const StepSpec& spec, const glm::tvec3<T>& p) {
    if (spec.grid) return spec.grid->lookup(p);
    return field_velocity<T>(spec.scene, p);
}

template <class T>
bool outside_domain(const glm::tvec3<T>& p) {
    return std::abs(p.x) > T(1) || std::abs(p.y) > T(1) || std::abs(p.z) > T(1);
}

// U[lo, hi) from draw `index` of the stream keyed by `seed`.
double uniform(std::uint64_t seed, std::uint64_t index, double lo, double hi) {
    return lo + (hi - lo) * unit_double(hash64(seed, index));
}

}  // namespace

namespace {

constexpr EnumName<ParticleScene> kSceneNames[] = {{ParticleScene::Gravity, "gravity"},
                                                   {ParticleScene::Rotation, "rotation"},
                                                   {ParticleScene::Saddle, "saddle"},
                                                   {ParticleScene::Abc, "abc"}};
constexpr EnumName<Integrator> kIntegratorNames[] = {{Integrator::Euler, "euler"},
                                                     {Integrator::Midpoint, "midpoint"},
                                                     {Integrator::Rk4, "rk4"}};

}  // namespace

ParticleScene particle_scene_from_name(const std::string& name) { return parse_enum(kSceneNames, "particle scene", name); }
const char* particle_scene_name(ParticleScene scene) { return name_of(kSceneNames, scene); }
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

void check_step_spec(const StepSpec& spec) {
    // A value outside the enums would reach step_particle's switches, perhaps on a worker thread where a
    // throw cannot be caught.
    const auto known = [](const char* name) { return std::string(name) != "unknown"; };
    if (!known(particle_scene_name(spec.scene)) || !known(integrator_name(spec.integrator)))
        throw Error("particle step: scene " + std::to_string(static_cast<int>(spec.scene)) + " or integrator " +
                    std::to_string(static_cast<int>(spec.integrator)) + " is not one of the known values");
    if (!std::isfinite(spec.h)) throw Error("particle step: h = " + std::to_string(spec.h) + " must be finite");
    if (!std::isfinite(spec.gravity))
        throw Error("particle step: gravity = " + std::to_string(spec.gravity) + " must be finite");
    if (spec.grid && spec.scene == ParticleScene::Gravity)
        throw Error("particle step: a velocity grid was given for the gravity scene, which has no field");
    if (spec.grid) {
        const VelocityGrid& grid = *spec.grid;
        const std::size_t side = static_cast<std::size_t>(grid.n);
        if (grid.n < VelocityGrid::kMinSide || grid.n > VelocityGrid::kMaxSide ||
            grid.texels.size() != 3 * side * side * side)
            throw Error("particle step: the velocity grid holds " + std::to_string(grid.texels.size()) +
                        " floats for side " + std::to_string(grid.n) + " (not one made by VelocityGrid::sample)");
    }
}

template <class T>
bool step_particle(const StepSpec& spec, glm::tvec3<T>& p, glm::tvec3<T>& v, const glm::tvec3<T>& p0,
                   const glm::tvec3<T>& v0) {
    const T h = T(spec.h);
    if (spec.scene == ParticleScene::Gravity) {
        const glm::tvec3<T> g(T(0), -T(spec.gravity), T(0));
        if (spec.integrator == Integrator::Euler)
            p = p + h * v;
        else
            p = p + h * v + (h * h / T(2)) * g;
        v = v + h * g;
    } else {
        const glm::tvec3<T> k1 = velocity_at(spec, p);
        switch (spec.integrator) {
            case Integrator::Euler: p = p + h * k1; break;
            case Integrator::Midpoint: {
                const glm::tvec3<T> k2 = velocity_at(spec, p + (h / T(2)) * k1);
                p = p + h * k2;
                break;
            }
            case Integrator::Rk4: {
                const glm::tvec3<T> k2 = velocity_at(spec, p + (h / T(2)) * k1);
                const glm::tvec3<T> k3 = velocity_at(spec, p + (h / T(2)) * k2);
                const glm::tvec3<T> k4 = velocity_at(spec, p + h * k3);
                p = p + (h / T(6)) * (k1 + T(2) * k2 + T(2) * k3 + k4);
                break;
            }
        }
        v = k1;
    }
    if (!outside_domain(p)) return false;
    p = p0;
    v = v0;
    return true;
}

double rotation_radius_growth_per_step(Integrator integrator, double h) {
    // R(ih) = a + ib: its real part takes the even powers, its imaginary part the odd ones.
    const double h2 = h * h;
    switch (integrator) {
        case Integrator::Euler: return std::sqrt(1.0 + h2);
        case Integrator::Midpoint: return std::hypot(1.0 - h2 / 2.0, h);
        case Integrator::Rk4: return std::hypot(1.0 - h2 / 2.0 + h2 * h2 / 24.0, h - h2 * h / 6.0);
    }
    throw Error("rotation_radius_growth_per_step: unknown integrator " + std::to_string(static_cast<int>(integrator)));
}

template glm::tvec3<float> field_velocity<float>(ParticleScene, glm::tvec3<float>);
template glm::tvec3<double> field_velocity<double>(ParticleScene, glm::tvec3<double>);
template bool step_particle<float>(const StepSpec&, glm::tvec3<float>&, glm::tvec3<float>&, const glm::tvec3<float>&,
                                   const glm::tvec3<float>&);
template bool step_particle<double>(const StepSpec&, glm::tvec3<double>&, glm::tvec3<double>&,
                                    const glm::tvec3<double>&, const glm::tvec3<double>&);

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
