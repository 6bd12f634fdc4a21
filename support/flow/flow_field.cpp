#include "support/flow/flow_field.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"
#include "common/core/splitmix64.h"
#include "support/flow/flow_sampling.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

namespace gsv {

using flow_detail::check_grid;
using flow_detail::DoubleField;
using flow_detail::fmt;
using flow_detail::sample_square;
using flow_detail::sample_texel_centres;
using flow_detail::square_in_texels;
using flow_detail::wide_in_texels;

namespace {

constexpr double kPi = glm::pi<double>();

// The double gyre of Shadden, Lekien and Marsden, "Definition and properties of Lagrangian coherent
// structures from finite-time Lyapunov exponents in two-dimensional aperiodic flows", Physica D 212
// (2005) 271-304, section 6.1, with their parameters A = 0.1, eps = 0.25, omega = 2 pi / 10. It is the
// stream function psi = A sin(pi f(x,t)) sin(pi y) on [0,2]x[0,1]: two counter-rotating cells whose
// dividing line oscillates about x = 1 with period 10. Velocity in domain units per unit time.
glm::dvec2 double_gyre(glm::dvec2 p, double t) {
    constexpr double A = 0.1, eps = 0.25, omega = 2.0 * kPi / 10.0;
    const double a = eps * std::sin(omega * t);
    const double b = 1.0 - 2.0 * eps * std::sin(omega * t);
    const double f = a * p.x * p.x + b * p.x;
    const double df_dx = 2.0 * a * p.x + b;
    return {-kPi * A * std::sin(kPi * f) * std::cos(kPi * p.y),
            kPi * A * std::cos(kPi * f) * std::sin(kPi * p.y) * df_dx};
}

}  // namespace

DoubleField flow_detail::sample_double_gyre(int width, int height, double time) {
    return sample_wide(width, height, [time](glm::dvec2 p) { return double_gyre(p, time); });
}

glm::vec2 FlowField::at(int x, int y) const {
    if (x < 0 || x >= width || y < 0 || y >= height)
        throw Error("FlowField::at: texel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                    std::to_string(width) + "x" + std::to_string(height) + " field");
    const std::size_t i = 2 * (static_cast<std::size_t>(y) * width + x);
    return {velocity[i], velocity[i + 1]};
}

float FlowField::max_speed() const {
    double largest = 0.0;
    for (std::size_t i = 0; i + 1 < velocity.size(); i += 2)
        largest = std::max(largest, std::hypot(double(velocity[i]), double(velocity[i + 1])));
    return static_cast<float>(largest);
}

FlowKind flow_kind_from_name(const std::string& name) { return parse_enum(kFlowKindNames, "flow", name); }

const char* flow_kind_name(FlowKind kind) { return name_of(kFlowKindNames, kind); }

namespace {

void check_flow_arguments(const char* who, int width, int height, double max_texels_per_step, double time) {
    check_grid(who, width, height, max_texels_per_step);
    if (!std::isfinite(time)) throw Error(std::string(who) + ": time must be finite, got " + fmt(time));
}

// The sum of the vortices' velocities at a domain point; the vortices are copied, so it outlives the caller's list.
auto vortex_sum(std::vector<Vortex> vortices) {
    return [vortices = std::move(vortices)](glm::dvec2 p) {
        glm::dvec2 sum(0.0);
        for (const Vortex& vortex : vortices) sum += vortex_velocity(vortex, p);
        return sum;
    };
}

// Calls use(in_texels) with the field of `kind` in texels at any point in texel coordinates, before scaling: what
// make_flow samples and analytic_flow scales, so that the two cannot drift apart. A call back rather than a returned
// std::function, so that the sweep's exact streamlines call the formulas through one std::function, not two: seven
// times faster for the linear fields.
template <typename Use>
auto with_field(FlowKind kind, int width, int height, double time, std::uint64_t seed, Use use) {
    switch (kind) {
        // Rotation, saddle and source are the linear flows v = M p whose critical point at the origin is
        // a centre, a saddle and an unstable node (Helman and Hesselink, "Representation and display of
        // vector field topology in fluid flow data sets", IEEE Computer 22(8), 1989): the three kinds of
        // critical point LIC images are read for.
        case FlowKind::Rotation:
            return use(square_in_texels(width, height, [](glm::dvec2 p) { return glm::dvec2(-p.y, p.x); }));
        case FlowKind::Saddle:
            return use(square_in_texels(width, height, [](glm::dvec2 p) { return glm::dvec2(p.x, -p.y); }));
        case FlowKind::Source:
            return use(square_in_texels(width, height, [](glm::dvec2 p) { return p; }));
        case FlowKind::DoubleGyre:
            return use(wide_in_texels(width, height, [time](glm::dvec2 p) { return double_gyre(p, time); }));
        case FlowKind::Vortices:
            return use(square_in_texels(width, height, vortex_sum(vortices_from_seed(seed))));
    }
    throw Error("make_flow: unknown FlowKind " + std::to_string(static_cast<int>(kind)));
}

}  // namespace

FlowField make_flow(FlowKind kind, int width, int height, double max_texels_per_step, double time,
                    std::uint64_t seed) {
    check_flow_arguments("make_flow", width, height, max_texels_per_step, time);
    return with_field(kind, width, height, time, seed, [&](auto in_texels) {
        return sample_texel_centres(width, height, in_texels).scaled_to(max_texels_per_step);
    });
}

VelocityAt analytic_flow(FlowKind kind, int width, int height, double max_texels_per_step, double time,
                         std::uint64_t seed) {
    check_flow_arguments("analytic_flow", width, height, max_texels_per_step, time);
    return with_field(kind, width, height, time, seed, [&](auto in_texels) {
        return flow_detail::scaled_everywhere(width, height, max_texels_per_step, in_texels);
    });
}

std::vector<Vortex> vortices_from_seed(std::uint64_t seed) {
    std::vector<Vortex> vortices(kVortexCount);
    std::uint64_t draw = 0;
    for (Vortex& vortex : vortices) {
        vortex.x = -0.8 + 1.6 * unit_double(hash64(seed, draw++));
        vortex.y = -0.8 + 1.6 * unit_double(hash64(seed, draw++));
        vortex.sign = (hash64(seed, draw++) >> 63) ? 1 : -1;
        vortex.core_radius = 0.15 + 0.25 * unit_double(hash64(seed, draw++));
    }
    return vortices;
}

// The Lamb-Oseen vortex (Lamb, "Hydrodynamics", 6th ed. 1932, section 334a; Oseen 1911): the viscous
// decay of a point vortex, with azimuthal speed proportional to (1 - exp(-r^2/c^2)) / r. Only the spatial
// profile is used here, frozen at one core radius c.
glm::dvec2 vortex_velocity(const Vortex& vortex, glm::dvec2 p) {
    const glm::dvec2 d = p - glm::dvec2(vortex.x, vortex.y);
    const double r2 = d.x * d.x + d.y * d.y;
    const double c2 = vortex.core_radius * vortex.core_radius;
    const double q = r2 / c2;
    // (1 - exp(-q)) / r2 is 0/0 at the centre and cancels catastrophically near it; its series
    // (1 - q/2 + ...) / c2 is accurate to double precision for q < 1e-8 and gives the limit 1/c2 at r = 0.
    // expm1 keeps the rest accurate.
    const double factor = q < 1e-8 ? (1.0 - 0.5 * q) / c2 : -std::expm1(-q) / r2;
    return static_cast<double>(vortex.sign) * factor * glm::dvec2(-d.y, d.x);
}

FlowField make_vortex_flow(const std::vector<Vortex>& vortices, int width, int height,
                           double max_texels_per_step) {
    check_grid("make_vortex_flow", width, height, max_texels_per_step);
    for (std::size_t i = 0; i < vortices.size(); ++i)
        if (!std::isfinite(vortices[i].core_radius) || vortices[i].core_radius <= 0)
            throw Error("make_vortex_flow: vortex " + std::to_string(i) + " has core radius " +
                        fmt(vortices[i].core_radius) + "; it must be positive and finite");
    return sample_square(width, height, vortex_sum(vortices)).scaled_to(max_texels_per_step);
}

namespace {

// The swirl in texels at a point in texel coordinates, unscaled; `who` names the caller in errors.
auto photo_swirl_in_texels(const char* who, int width, int height, double max_texels_per_step, double cx, double cy,
                           double radius) {
    check_grid(who, width, height, max_texels_per_step);
    if (!std::isfinite(cx) || !std::isfinite(cy))
        throw Error(std::string(who) + ": centre (" + fmt(cx) + ", " + fmt(cy) + ") must be finite");
    if (!std::isfinite(radius) || radius < 0)
        throw Error(std::string(who) + ": radius must be finite and >= 0, got " + fmt(radius));
    const glm::dvec2 centre(cx * width, cy * height);
    const double outer = radius * std::min(width, height);
    return [centre, outer](glm::dvec2 q) {
        const glm::dvec2 d = q - centre;
        const double r = std::sqrt(d.x * d.x + d.y * d.y);
        // Tested as r < outer (not via smoothstep alone) so the fade is exactly zero from `radius` on,
        // and a zero radius never divides by zero.
        const double weight = r < outer ? 1.0 - flow_detail::smoothstep01((r - 0.5 * outer) / (0.5 * outer)) : 0.0;
        return weight * glm::dvec2(-d.y, d.x);
    };
}

}  // namespace

FlowField make_photo_swirl(int width, int height, double max_texels_per_step, double cx, double cy,
                           double radius) {
    const auto in_texels =
        photo_swirl_in_texels("make_photo_swirl", width, height, max_texels_per_step, cx, cy, radius);
    return sample_texel_centres(width, height, in_texels).scaled_to(max_texels_per_step);
}

VelocityAt analytic_photo_swirl(int width, int height, double max_texels_per_step, double cx, double cy,
                                double radius) {
    return flow_detail::scaled_everywhere(
        width, height, max_texels_per_step,
        photo_swirl_in_texels("analytic_photo_swirl", width, height, max_texels_per_step, cx, cy, radius));
}

}  // namespace gsv
