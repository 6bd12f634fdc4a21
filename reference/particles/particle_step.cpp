// One step of one particle, in float and in double: the CPU yardstick of lab 05's integrators.
#include "reference/particles/particle_step.h"

#include "common/core/error.h"
#include "reference/particles/grid_lookup.h"

#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {
namespace {

// The field where the integrator asks for it: the grid's lookup when there is one (what the shader's
// texture() returns), else the formula.
template <class T>
glm::tvec3<T> velocity_at(const StepSpec& spec, const glm::tvec3<T>& p) {
    if (spec.grid) return grid_lookup(*spec.grid, p);
    return field_velocity<T>(spec.scene, p);
}

template <class T>
bool outside_domain(const glm::tvec3<T>& p) {
    return std::abs(p.x) > T(1) || std::abs(p.y) > T(1) || std::abs(p.z) > T(1);
}

}  // namespace

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

template bool step_particle<float>(const StepSpec&, glm::tvec3<float>&, glm::tvec3<float>&, const glm::tvec3<float>&,
                                   const glm::tvec3<float>&);
template bool step_particle<double>(const StepSpec&, glm::tvec3<double>&, glm::tvec3<double>&,
                                    const glm::tvec3<double>&, const glm::tvec3<double>&);

}  // namespace gsv
