// The Marschner-Lobb signal: its value, exact gradient, sampled volume and exact ray-isosurface hits.
#include "support/volume/marschner_lobb.h"

#include "common/core/error.h"
#include "support/geometry/ray_box.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {
namespace {

constexpr double kPi = 3.14159265358979323846;
// A bound on the march, so a tiny step is refused rather than run for hours (or overflow a long).
constexpr double kMaxRaySteps = 1e9;

void check(glm::dvec3 p, const MarschnerLobb& params, const char* who) {
    if (!std::isfinite(params.f_m) || !std::isfinite(params.alpha) || params.alpha == -1)
        throw Error(std::string(who) + ": f_M " + std::to_string(params.f_m) + " and alpha " +
                    std::to_string(params.alpha) + " must be finite, with alpha != -1");
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw Error(std::string(who) + ": point (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
                    std::to_string(p.z) + ") must be finite");
}

// sin(u) / u, and its limit 1 at u = 0. sin(u) / u itself is accurate for every other u, subnormals
// included (sin(u) = u there), so only exact zero needs its own branch.
double sinc(double u) { return u == 0 ? 1.0 : std::sin(u) / u; }

}  // namespace

double marschner_lobb(glm::dvec3 p, const MarschnerLobb& params) {
    check(p, params, "marschner_lobb");
    const double r = std::hypot(p.x, p.y);
    const double rho_r = std::cos(2 * kPi * params.f_m * std::cos(kPi * r / 2));
    return (1 - std::sin(kPi * p.z / 2) + params.alpha * (1 + rho_r)) / (2 * (1 + params.alpha));
}

glm::dvec3 marschner_lobb_gradient(glm::dvec3 p, const MarschnerLobb& params) {
    check(p, params, "marschner_lobb_gradient");
    const double r = std::hypot(p.x, p.y);
    const double scale = 1 / (2 * (1 + params.alpha));
    // rho_r'(r) = sin(2 pi f_M cos(pi r / 2)) 2 pi f_M sin(pi r / 2) pi / 2, and d r / dx = x / r. The
    // product's sin(pi r / 2) / r = (pi / 2) sinc(pi r / 2) is finite at r = 0, where the whole x and y
    // part is 0 because x and y are.
    const double drho_r_over_r = std::sin(2 * kPi * params.f_m * std::cos(kPi * r / 2)) * 2 * kPi * params.f_m *
                                 (kPi / 2) * (kPi / 2) * sinc(kPi * r / 2);
    const double radial = scale * params.alpha * drho_r_over_r;
    return {radial * p.x, radial * p.y, -scale * (kPi / 2) * std::cos(kPi * p.z / 2)};
}

Volume make_marschner_lobb_volume(int n, const MarschnerLobb& params) {
    if (n < 2 || n > kMaxVolumeSide || std::size_t(n) * std::size_t(n) * std::size_t(n) > kMaxVolumeVoxels)
        throw Error("make_marschner_lobb_volume: side " + std::to_string(n) + " is not in 2.." +
                    std::to_string(kMaxVolumeSide) + " with at most " + std::to_string(kMaxVolumeVoxels) + " voxels");
    check(glm::dvec3(0.0), params, "make_marschner_lobb_volume");
    Volume volume;
    volume.nx = volume.ny = volume.nz = n;
    volume.spacing = glm::dvec3(2.0 / n);
    volume.name = "marschner_lobb";
    volume.values.resize(std::size_t(n) * std::size_t(n) * std::size_t(n));
    const auto centre = [n](int i) { return -1.0 + (2.0 * i + 1.0) / n; };
    std::size_t at = 0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                volume.values[at++] = static_cast<float>(marschner_lobb({centre(i), centre(j), centre(k)}, params));
    volume.update_range();
    return volume;
}

std::optional<double> marschner_lobb_ray_hit(glm::dvec3 origin, glm::dvec3 direction, double t0, double t1, double iso,
                                             const MarschnerLobb& params, double step) {
    check(origin, params, "marschner_lobb_ray_hit");
    if (!std::isfinite(t0) || !std::isfinite(t1) || t1 < t0 || !std::isfinite(iso) || !std::isfinite(step) || step <= 0)
        throw Error("marschner_lobb_ray_hit: t0 " + std::to_string(t0) + ", t1 " + std::to_string(t1) + ", iso " +
                    std::to_string(iso) + " and step " + std::to_string(step) +
                    " must be finite, with t0 <= t1 and step > 0");
    const std::optional<RaySpan> span = ray_box_span(origin, direction, glm::dvec3(-1.0), glm::dvec3(1.0));
    if (!span) return std::nullopt;
    const double a = std::max(t0, span->entry), b = std::min(t1, span->exit);
    if (a > b) return std::nullopt;

    // Points on the ray may stray a rounding error outside the box; rho is defined there all the same.
    const auto g = [&](double t) { return marschner_lobb(origin + t * direction, params) - iso; };
    double ta = a, ga = g(ta);
    if (ga == 0) return ta;
    // Both a and b are finite, and the clipped span is at most the box's diagonal long, so the count is small.
    const double count = std::ceil((b - a) * glm::length(direction) / step);
    if (count > kMaxRaySteps)
        throw Error("marschner_lobb_ray_hit: step " + std::to_string(step) + " would take " + std::to_string(count) +
                    " steps through the box, more than " + std::to_string(kMaxRaySteps));
    const long steps = std::max(1L, static_cast<long>(count));
    for (long s = 1; s <= steps; ++s) {
        const double tb = s == steps ? b : a + (b - a) * (double(s) / double(steps));
        const double gb = g(tb);
        if (gb == 0) return tb;
        if ((ga < 0) != (gb < 0)) {
            // Bisection keeps ga and gb of opposite signs until no double lies between ta and tb.
            double lo = ta, hi = tb, glo = ga;
            for (;;) {
                const double mid = lo + (hi - lo) / 2;
                if (mid <= lo || mid >= hi) break;
                const double gm = g(mid);
                if (gm == 0) return mid;
                if ((gm < 0) == (glo < 0)) lo = mid, glo = gm;
                else hi = mid;
            }
            return lo;
        }
        ta = tb, ga = gb;
    }
    return std::nullopt;
}

}  // namespace gsv
