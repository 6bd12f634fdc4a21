// The exact LIC that lab 02's sweep measures against (support/flow/lic_reference.h): the continuous fields it
// integrates are make_flow's, its RK4 streamlines are the closed-form ones where there is a closed form and have
// converged where there is none, its hard cases give what they must, and with it the sweep tells Euler from
// midpoint, which a longer filter as reference could not.
#include "catch.hpp"
#include "lab_runner.h"
#include "test_support.h"

#include "support/flow/flow_field.h"
#include "reference/flow/lic_reference.h"
#include "support/flow/noise.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

using glm::dvec2;
using gsv::FlowKind;

namespace {

const FlowKind kKinds[] = {FlowKind::Rotation, FlowKind::Saddle, FlowKind::Source, FlowKind::DoubleGyre,
                           FlowKind::Vortices};

// The linear fields in texel coordinates about the grid's centre, u = q - (W/2, H/2), before scaling: du/dt = A u.
// A domain unit is W/2 texels across and H/2 up, so the rotation (-y, x) becomes (-u.y W/H, u.x H/W): an ellipse
// on a grid that is not square. Written out here from the formulas, not taken from the code under test.
struct Linear {
    double a, b, c, d;  // A = [[a, b], [c, d]]
    dvec2 times(dvec2 u) const { return {a * u.x + b * u.y, c * u.x + d * u.y}; }
};

Linear linear_field(FlowKind kind, int width, int height) {
    const double w = width, h = height;
    if (kind == FlowKind::Rotation) return {0, -w / h, h / w, 0};
    if (kind == FlowKind::Saddle) return {1, 0, 0, -1};
    return {1, 0, 0, 1};
}

// make_flow's scale: the requested speed over the largest speed at the texel centres.
double linear_scale(const Linear& field, int width, int height, double speed) {
    double largest = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            largest = std::max(largest, glm::length(field.times(dvec2(x + 0.5 - width / 2.0, y + 0.5 - height / 2.0))));
    return speed / largest;
}

// exp(t s A) u: A^2 = -I for the rotation, so exp(tA) = cos(t) I + sin(t) A; the others are diagonal.
dvec2 linear_flow(FlowKind kind, const Linear& field, double s, double t, dvec2 u) {
    if (kind == FlowKind::Rotation) return std::cos(s * t) * u + std::sin(s * t) * field.times(u);
    if (kind == FlowKind::Saddle) return {std::exp(s * t) * u.x, std::exp(-s * t) * u.y};
    return std::exp(s * t) * u;
}

// to_rgba8's rounding, written out again.
int level(double value) { return static_cast<int>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0)); }

// The noise value of texel (x, y), y from the bottom.
double noise_at(const std::vector<float>& noise, int width, int x, int y) {
    return noise[static_cast<std::size_t>(y) * width + x];
}

// The image's grey level at (x, y) with y from the BOTTOM, as the noise is indexed.
int grey(const gsv::Image& image, int x, int y) { return image.at(x, image.height - 1 - y)[0]; }

}  // namespace

TEST_CASE("analytic_flow is make_flow's field: equal at every texel centre once rounded to float", "[unit][flow]") {
    for (auto [width, height] : {std::pair{64, 64}, std::pair{65, 33}, std::pair{80, 48}})
        for (double speed : {1.0, 2.5})
            for (FlowKind kind : kKinds) {
                INFO(gsv::flow_kind_name(kind) << " " << width << "x" << height << " speed " << speed);
                const gsv::FlowField field = gsv::make_flow(kind, width, height, speed, 2.5, 3);
                const gsv::VelocityAt exact = gsv::analytic_flow(kind, width, height, speed, 2.5, 3);
                for (int y = 0; y < height; ++y)
                    for (int x = 0; x < width; ++x)
                        REQUIRE(glm::vec2(exact(dvec2(x + 0.5, y + 0.5))) == field.at(x, y));
            }
    const gsv::FlowField swirl = gsv::make_photo_swirl(90, 70, 1.5, 0.5, 0.62, 0.28);
    const gsv::VelocityAt exact_swirl = gsv::analytic_photo_swirl(90, 70, 1.5, 0.5, 0.62, 0.28);
    for (int y = 0; y < 70; ++y)
        for (int x = 0; x < 90; ++x) REQUIRE(glm::vec2(exact_swirl(dvec2(x + 0.5, y + 0.5))) == swirl.at(x, y));
    CHECK(gsv::test::gsv_error_message([] { gsv::analytic_flow(FlowKind::Rotation, 0, 8, 1.0); }) ==
          "analytic_flow: width must be 1..8192, got 0");
    CHECK(gsv::test::gsv_error_message([] { gsv::analytic_photo_swirl(8, 8, 1.0, 0.5, 0.5, -1.0); }) ==
          "analytic_photo_swirl: radius must be finite and >= 0, got -1");
}

TEST_CASE("exact streamlines of the linear fields are their closed forms, the rotation an ellipse on a wide grid",
          "[unit][flow]") {
    // Measured, after up to 100 steps either way: 1.7e-12 texels (a texel out from the centre) at speed 1, and
    // 1.7e-9 at speed 4, where a substep turns the 64x64 rotation by 0.011 radian.
    for (auto [width, height] : {std::pair{64, 64}, std::pair{80, 48}})
        for (double speed : {1.0, 4.0})
            for (FlowKind kind : {FlowKind::Rotation, FlowKind::Saddle, FlowKind::Source}) {
                INFO(gsv::flow_kind_name(kind) << " " << width << "x" << height << " speed " << speed);
                const Linear field = linear_field(kind, width, height);
                const double s = linear_scale(field, width, height, speed);
                const gsv::VelocityAt velocity = gsv::analytic_flow(kind, width, height, speed);
                const dvec2 centre(width / 2.0, height / 2.0);
                double worst = 0;
                for (const dvec2& start : {dvec2(10.25, 7.5), dvec2(40.5, 30.75), dvec2(31.0, 20.0), dvec2(60.5, 40.5)})
                    for (int steps : {1, 7, 100, -1, -7, -100}) {
                        const dvec2 traced = gsv::trace_streamline(velocity, start, steps);
                        const dvec2 expected = centre + linear_flow(kind, field, s, steps, start - centre);
                        // Relative beyond a texel from the centre: the source carries 100 steps out to 1e3 texels.
                        const double out = std::max(1.0, glm::length(expected - centre));
                        worst = std::max(worst, glm::length(traced - expected) / out);
                    }
                INFO("worst distance from the closed form: " << worst << " texels (per texel from the centre)");
                CHECK(worst < (speed == 1.0 ? 1e-10 : 1e-8));
            }
}

TEST_CASE("normalised exact streamlines run at unit speed: circles of the square rotation, and into the source's "
          "centre, where they end",
          "[unit][flow]") {
    const dvec2 centre(32.0, 32.0);
    const gsv::StreamlineOptions normalized{true};
    // A circle of radius 10 texels is swept at 0.1 radian a step. Measured: 7e-9 texels off after 100 steps.
    const gsv::VelocityAt rotation = gsv::analytic_flow(FlowKind::Rotation, 64, 64, 1.0);
    for (int steps : {1, 25, 100, -100}) {
        const dvec2 traced = gsv::trace_streamline(rotation, centre + dvec2(10.0, 0.0), steps, normalized);
        const dvec2 expected = centre + 10.0 * dvec2(std::cos(0.1 * steps), std::sin(0.1 * steps));
        INFO(steps << " steps: " << glm::length(traced - expected) << " texels off the circle");
        CHECK(glm::length(traced - expected) < 1e-7);
    }
    // Backwards from 5 texels out along (3, 4), a unit a step, the source's centre is reached at s = 5, between two
    // samples of a substep, and the streamline stays there: no NaN, no hopping about the zero.
    const gsv::VelocityAt source = gsv::analytic_flow(FlowKind::Source, 64, 64, 1.0);
    const dvec2 start = centre + dvec2(3.0, 4.0);
    CHECK(glm::length(gsv::trace_streamline(source, start, -3, normalized) - (centre + dvec2(1.2, 1.6))) < 1e-9);
    for (int steps : {-5, -6, -50}) {
        const dvec2 traced = gsv::trace_streamline(source, start, steps, normalized);
        INFO(steps << " steps: " << glm::length(traced - centre) << " texels from the centre");
        CHECK(glm::length(traced - centre) < 1e-9);
    }
    CHECK(glm::length(gsv::trace_streamline(source, start, 10, normalized) - (centre + dvec2(9.0, 12.0))) < 1e-9);
}

TEST_CASE("exact streamlines have converged: four times the substeps moves none by 1e-6 texels (1e-5 normalised)",
          "[unit][flow]") {
    // 64x64 at speed 1: the lab's smallest vortex cores are fewest texels across here. Measured, 8 against 32
    // substeps over 100 steps: 8e-9 texels on the vortices, 7e-10 on the double gyre (4 against 16: 1.3e-7 and
    // 1.1e-8). Normalised, the streamlines that circle a vortex's core or pass near a zero turn sharply: 1.1e-6 on
    // the vortices and 1.9e-6 on the double gyre at t = 2.5, with the halving near zeros (without it, 5e-3 on a
    // streamline circling 0.7 texels from a vortex's centre).
    struct Case {
        FlowKind kind;
        double time;
        bool normalized;
        double bound;
    };
    for (const Case& c : {Case{FlowKind::Vortices, 0.0, false, 1e-6}, Case{FlowKind::DoubleGyre, 0.0, false, 1e-6},
                          Case{FlowKind::DoubleGyre, 2.5, false, 1e-6}, Case{FlowKind::Vortices, 0.0, true, 1e-5},
                          Case{FlowKind::DoubleGyre, 2.5, true, 1e-5}}) {
        const gsv::VelocityAt velocity = gsv::analytic_flow(c.kind, 64, 64, 1.0, c.time, 1);
        double worst = 0;
        for (int i = 0; i < 8; ++i)
            for (int j = 0; j < 8; ++j) {
                const dvec2 start((i + 0.37) * 8.0, (j + 0.61) * 8.0);
                for (int steps : {100, -100}) {
                    const gsv::StreamlineOptions ours{c.normalized, gsv::kLicSubsteps};
                    const gsv::StreamlineOptions finer{c.normalized, 4 * gsv::kLicSubsteps};
                    worst = std::max(worst, glm::length(gsv::trace_streamline(velocity, start, steps, ours) -
                                                        gsv::trace_streamline(velocity, start, steps, finer)));
                }
            }
        INFO(gsv::flow_kind_name(c.kind) << " at t = " << c.time << (c.normalized ? ", normalised" : "") << ": "
                                         << worst << " texels apart");
        CHECK(worst < c.bound);
    }
}

TEST_CASE("exact LIC: a still field gives the noise itself, top row first, and so does length 0", "[unit][flow]") {
    const int width = 24, height = 16;
    const std::vector<float> noise = gsv::white_noise(width, height, 5);
    for (bool normalized : {false, true}) {
        const gsv::VelocityAt still = gsv::analytic_flow(FlowKind::Source, width, height, 0.0);
        const std::vector<gsv::Image> images = gsv::exact_lic(still, noise, width, height, {0, 30}, {normalized});
        const gsv::Image moving = gsv::exact_lic(gsv::analytic_flow(FlowKind::Rotation, width, height, 1.0), noise,
                                                 width, height, {0}, {normalized})[0];
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const int expected = level(noise_at(noise, width, x, y));
                REQUIRE(grey(images[0], x, y) == expected);
                REQUIRE(grey(images[1], x, y) == expected);
                REQUIRE(grey(moving, x, y) == expected);
                REQUIRE(images[1].at(x, y)[3] == 255);
            }
    }
}

TEST_CASE("exact LIC: a streamline that leaves the grid stops there, and nothing outside is counted", "[unit][flow]") {
    // One texel a step to the right from a texel centre lands on texel centres: with a length longer than the grid
    // every pixel of a row averages exactly that row's texels, each once. A sample beyond the edge, clamped to the
    // edge texel and counted, would weigh the ends of the row more.
    const int width = 20, height = 6;
    const std::vector<float> noise = gsv::white_noise(width, height, 9);
    const gsv::VelocityAt right = [](dvec2) { return dvec2(1.0, 0.0); };
    const gsv::Image image = gsv::exact_lic(right, noise, width, height, {2 * width})[0];
    for (int y = 0; y < height; ++y) {
        double sum = 0;
        for (int x = 0; x < width; ++x) sum += noise_at(noise, width, x, y);
        for (int x = 0; x < width; ++x) REQUIRE(std::abs(grey(image, x, y) - level(sum / width)) <= 1);
    }
    // The same, normalised, through the source's centre on an odd grid: forwards out of the grid, backwards into the
    // centre texel, which each later sample repeats. On texel centres, so the average is of texels.
    const int n = 33, centre = 16;
    const std::vector<float> odd = gsv::white_noise(n, n, 2);
    const gsv::VelocityAt source = gsv::analytic_flow(FlowKind::Source, n, n, 1.0);
    const int length = 10;
    const gsv::Image lic = gsv::exact_lic(source, odd, n, n, {length}, {true})[0];
    CHECK(grey(lic, centre, centre) == level(noise_at(odd, n, centre, centre)));  // on the zero: it never moves
    double sum = noise_at(odd, n, centre + 3, centre) + noise_at(odd, n, centre + 2, centre) +
                 noise_at(odd, n, centre + 1, centre) + (length - 2) * noise_at(odd, n, centre, centre);
    for (int k = 1; k <= length; ++k) sum += noise_at(odd, n, centre + 3 + k, centre);
    CHECK(grey(lic, centre + 3, centre) == level(sum / (2 * length + 1)));
    // Forwards from the right column, the first sample is outside: the pixel averages its own and the 10 before.
    sum = 0;
    for (int k = 0; k <= length; ++k) sum += noise_at(odd, n, n - 1 - k, centre);
    CHECK(grey(lic, n - 1, centre) == level(sum / (length + 1)));
}

TEST_CASE("exact LIC: every length of one walk is the image walked for it alone, in any order", "[unit][flow]") {
    const int width = 40, height = 30;
    const std::vector<float> noise = gsv::white_noise(width, height, 4);
    const gsv::VelocityAt vortices = gsv::analytic_flow(FlowKind::Vortices, width, height, 1.5, 0, 2);
    const std::vector<gsv::Image> together = gsv::exact_lic(vortices, noise, width, height, {12, 3, 7});
    gsv::ExactLic lic(vortices, noise, width, height);
    const gsv::Image twelve = lic.image(12), three = lic.image(3);  // the shorter one after: walked afresh
    CHECK(together[0].rgba == gsv::exact_lic(vortices, noise, width, height, {12})[0].rgba);
    CHECK(together[1].rgba == gsv::exact_lic(vortices, noise, width, height, {3})[0].rgba);
    CHECK(together[2].rgba == gsv::exact_lic(vortices, noise, width, height, {7})[0].rgba);
    CHECK(twelve.rgba == together[0].rgba);
    CHECK(three.rgba == together[1].rgba);
    CHECK(together[0].rgba != together[1].rgba);
}

TEST_CASE("exact LIC refuses bad arguments with one line naming the value", "[unit][flow]") {
    const std::vector<float> noise(16, 0.5f);
    const gsv::VelocityAt still = [](dvec2) { return dvec2(0.0); };
    using gsv::test::gsv_error_message;
    CHECK(gsv_error_message([&] { gsv::exact_lic(still, noise, 4, 4, {-1}); }) ==
          "exact_lic: a length must be >= 0, got -1");
    CHECK(gsv_error_message([&] { gsv::exact_lic(still, noise, 4, 5, {1}); }) ==
          "exact_lic: the noise holds 16 values, not 4x5");
    CHECK(gsv_error_message([&] { gsv::exact_lic(still, noise, 0, 4, {1}); }) ==
          "exact_lic: width must be 1..8192, got 0");
    CHECK(gsv_error_message([&] { gsv::exact_lic(still, noise, 4, 4, {1}, {false, 0}); }) ==
          "exact_lic: substeps must be >= 1, got 0");
    CHECK(gsv_error_message([&] { gsv::exact_lic(gsv::VelocityAt(), noise, 4, 4, {1}); }) ==
          "exact_lic: no velocity field given");
    CHECK(gsv_error_message([&] { gsv::ExactLic().image(1); }) == "exact_lic: no velocity field given");
}

TEST_CASE("lab02: the sweep measures against the exact LIC, and midpoint steps come out well below Euler's",
          "[lab][lab02]") {
    gsv::test::TempDir dir;
    const auto sweep = [&](const std::vector<std::string>& settings) {
        std::vector<std::string> args{"sweep", "--size", "64x64", "--frames", "1", "--warmup", "0", "--knob", "length",
                                      "--values", "5,25", "--out-dir", dir.path().string()};
        for (const auto& s : settings) args.insert(args.end(), {"--set", s});
        const auto run = gsv::test::run_lab("lab02_solution", args, dir.path());
        INFO(run.process.output);
        REQUIRE(run.exit_code() == 0);
        const auto rows = gsv::test::lines_of(gsv::test::read_text(dir.path("lab02-sweep.csv")));
        REQUIRE(rows.size() == 5);  // the header, then euler 5, euler 25, midpoint 5, midpoint 25
        REQUIRE(rows[2].rfind("euler,25,", 0) == 0);
        REQUIRE(rows[4].rfind("midpoint,25,", 0) == 0);
        return rows;
    };
    const auto rows = sweep({"field=rotation"});
    const auto rmse = [&](int row) { return gsv::test::csv_value(rows[0], rows[row], "rmse"); };
    INFO(rows[1] << "\n" << rows[2] << "\n" << rows[3] << "\n" << rows[4]);
    // Measured on llvmpipe: RMSE 0.90 and 1.83 (Euler, lengths 5 and 25), 0.08 and 0.27 (midpoint). Midpoint at
    // length 5 agrees with the exact streamlines to a tenth of a level: the reference is the same LIC, not a
    // longer one.
    CHECK(rmse(4) < 0.4 * rmse(2));
    CHECK(rmse(2) > rmse(1));
    CHECK(rmse(3) < 0.3);
    const std::string exact = ",LIC of the same length along the exact streamlines of the analytic field";
    CHECK(rows[1].find(exact) != std::string::npos);
    // A photograph has no exact LIC here: the reference is a long midpoint one, and says what that measures.
    const auto photo = sweep({"input=photo", "field=swirl"});
    CHECK(photo[1].find(",midpoint LIC of length 200") != std::string::npos);
    CHECK(photo[1].find("measures the length as well as the accuracy (step=midpoint length=200)") != std::string::npos);
}
