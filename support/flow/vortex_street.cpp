// The von Karman vortex street, the unsteady flow of lab 03's time-varying LIC.
//
// von Karman, "Ueber den Mechanismus des Widerstandes, den ein bewegter Koerper in einer Fluessigkeit
// erfaehrt", Nachrichten der Gesellschaft der Wissenschaften zu Goettingen, Math.-Phys. Klasse, 1911,
// 509-517, and its second part, 1912, 547-556: behind a bluff body the wake rolls up into two staggered
// rows of vortices of opposite sign. Rows of point vortices a apart, the rows h apart, escape instability
// (to first order) only for cosh(pi h / a) = sqrt(2), h / a = 0.2806 (the 0.281 usually quoted), and such
// a street moves through the fluid, against the stream, at u_s = Gamma / (2 a) tanh(pi h / a), Gamma being
// each vortex's circulation.
//
// Here: a uniform stream U to the right on [0,2]x[0,1] plus the two rows at y = 1/2 +- h/2, made of the
// kit's Lamb-Oseen vortices (vortex_velocity) so their cores are smooth where point vortices would be
// singular. The street drifts downstream at U - u_s. It is a kinematic model: the vortices are placed,
// not integrated, and the cores do not grow.
#include "support/flow/flow_field.h"

#include "common/core/error.h"
#include "support/flow/flow_sampling.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace gsv {
namespace {

constexpr double kPi = glm::pi<double>();
constexpr double kStream = 1.0;  // U, along +x
// Four spacings across the domain's length of 2: several vortices in view, each core resolved by a few
// texels on a 128x64 grid.
constexpr double kSpacing = 0.5;
// A tenth of the spacing: well inside half the row gap (0.07), so opposite vortices do not merge.
constexpr double kCoreRadius = 0.05;
// The street's speed through the fluid, u_s, as a fraction of U: the vortices drift at 0.8 U, clearly
// slower than the stream they sit in, which is what makes the pattern visibly lag the flow in an animation.
constexpr double kSelfSpeed = 0.2;

// h from von Karman's criterion itself, acosh(sqrt 2) / pi = ln(1 + sqrt 2) / pi, not the rounded 0.281.
double row_gap() { return kSpacing * std::log(1.0 + std::sqrt(2.0)) / kPi; }

// Each vortex's circulation Gamma, from u_s = Gamma / (2 a) tanh(pi h / a), divided by 2 pi because
// vortex_velocity's far field is 1 / r, the velocity of circulation 2 pi.
double strength() { return 2.0 * kSpacing * kSelfSpeed / std::tanh(kPi * row_gap() / kSpacing) / (2.0 * kPi); }

// A row is kSlots spacings long, from x = kFirstX, well past both ends of the domain. A vortex enters at
// the upstream end with zero strength, grows over kRamp spacings, and fades over the last kRamp, like a
// vortex being shed and then dying away. Without that, one vortex would appear at one end and another
// vanish at the other each period, and the whole field would jump in time. Full strength covers
// x in [-1, 3] (the lower row [-0.75, 3.25]), two spacings beyond the domain on each side.
constexpr int kSlots = 12;
constexpr double kRamp = 2.0;
constexpr double kFirstX = -4.0 * kSpacing;

double ramp_weight(double s) {
    return flow_detail::smoothstep01(s / kRamp) * flow_detail::smoothstep01((kSlots - s) / kRamp);
}

}  // namespace

glm::dvec2 vortex_street_velocity(glm::dvec2 p, double phase) {
    if (!std::isfinite(phase))
        throw Error("vortex_street_velocity: phase must be finite, got " + flow_detail::fmt(phase));
    const double gamma = strength();
    const double half_gap = 0.5 * row_gap();
    glm::dvec2 velocity(kStream, 0.0);
    // Every vortex slot s = m + phase (m an integer) in [0, kSlots]: the pattern at phase + 1 has the same
    // slots, each taken by the next vortex upstream, and the slots at the ends have zero weight. So the
    // terms, even their order, are identical for phase and phase + 1; periodicity is not imposed by
    // reducing phase modulo 1, it follows from the construction.
    for (double m = std::ceil(-phase); m + phase <= kSlots; m += 1.0) {
        const double s = m + phase;
        const double weight = gamma * ramp_weight(s);
        // Upper row clockwise, lower row counter-clockwise and half a spacing downstream, as in a wake
        // where the stream runs to +x: then each row pushes the other upstream, so the street lags U.
        const Vortex upper{kFirstX + s * kSpacing, 0.5 + half_gap, -1, kCoreRadius};
        const Vortex lower{kFirstX + (s + 0.5) * kSpacing, 0.5 - half_gap, 1, kCoreRadius};
        velocity += weight * vortex_velocity(upper, p);
        velocity += weight * vortex_velocity(lower, p);
    }
    return velocity;
}

double vortex_street_drift() { return kStream - kSelfSpeed; }

FlowSequence make_vortex_street(int width, int height, int frames, double max_texels_per_step) {
    return flow_detail::scaled_together("make_vortex_street", width, height, frames, max_texels_per_step, [&](int k) {
        const double phase = static_cast<double>(k) / frames;
        return flow_detail::sample_wide(width, height, [&](glm::dvec2 p) { return vortex_street_velocity(p, phase); });
    });
}

}  // namespace gsv
