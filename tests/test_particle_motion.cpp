#include "catch.hpp"

#include "common/core/error.h"
#include "reference/particles/grid_lookup.h"
#include "reference/particles/particle_cpu.h"
#include "support/particles/particle_grid.h"
#include "support/particles/particle_motion.h"
#include "test_support.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using gsv::Integrator;
using gsv::ParticleScene;
using gsv::ParticleSet;
using gsv::StepSpec;
using gsv::VelocityGrid;
using gsv::test::gsv_error_message;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

template <class V>
bool same_bits(const V& a, const V& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <class V>
bool same_bits(const std::vector<V>& a, const std::vector<V>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(V)) == 0;
}

// `steps` steps of one particle that starts at its origin (p0, v0), in T.
template <class T>
glm::tvec3<T> run(const StepSpec& spec, glm::tvec3<T> p0, glm::tvec3<T> v0, int steps, glm::tvec3<T>* v_out = nullptr) {
    glm::tvec3<T> p = p0, v = v0;
    for (int s = 0; s < steps; ++s) gsv::step_particle<T>(spec, p, v, p0, v0);
    if (v_out) *v_out = v;
    return p;
}

// A field scene's particles starting at `starts` with the field's velocity there.
ParticleSet field_set(ParticleScene scene, const std::vector<glm::dvec3>& starts) {
    ParticleSet set;
    for (const glm::dvec3& p : starts) {
        const glm::vec4 position(glm::vec3(p), 1.0f);
        const glm::vec4 velocity(glm::vec3(gsv::field_velocity<double>(scene, glm::dvec3(glm::vec3(p)))), 0.0f);
        set.positions.push_back(position);
        set.velocities.push_back(velocity);
        set.origins.push_back({position, velocity});
    }
    return set;
}

// `count` seeded starting points well inside D, in [-extent, extent)^3.
std::vector<glm::dvec3> inner_points(std::size_t count, double extent, std::uint64_t seed) {
    const ParticleSet spread = gsv::make_particles(ParticleScene::Abc, count, seed);
    std::vector<glm::dvec3> points;
    for (const glm::vec4& p : spread.positions) points.push_back(extent * glm::dvec3(p));
    return points;
}

// Root-mean-square distance between two runs' positions.
double rms_distance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += glm::dot(a[i] - b[i], a[i] - b[i]);
    return std::sqrt(sum / static_cast<double>(a.size()));
}

bool none_exited(const gsv::ReferenceRun& run) {
    return std::none_of(run.exited.begin(), run.exited.end(), [](bool e) { return e; });
}

std::vector<std::size_t> all_indices(std::size_t count) { return gsv::reference_sample(count, count); }

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Integrators on fields with known answers

TEST_CASE("particles: one turn of rotation gives each integrator's closed-form radius ratio", "[unit][particles]") {
    // One step multiplies z = x + iy by the method's stability polynomial at ih; 63 steps of 0.1 is one turn.
    const double h = 0.1;
    const int steps = 63;
    const std::complex<double> ih(0, h);
    const double euler = std::pow(1 + h * h, steps / 2.0);
    const double midpoint = std::pow(1 + h * h * h * h / 4, steps / 2.0);
    const std::complex<double> rk4_factor = 1.0 + ih + ih * ih / 2.0 + ih * ih * ih / 6.0 + ih * ih * ih * ih / 24.0;
    const double rk4 = std::pow(std::abs(rk4_factor), steps);
    // The figures quoted in the lab sheet, to their digits.
    CHECK(std::abs(euler - 1.368) < 0.0005);
    CHECK(std::abs(midpoint - 1.0008) < 0.00005);
    CHECK(std::abs(rk4 - 0.9999996) < 0.00000005);

    const double expected[] = {euler, midpoint, rk4};
    for (int m = 0; m < 3; ++m) {
        INFO(gsv::integrator_name(gsv::kIntegrators[m]));
        // The sweep's closed-form column, written another way.
        CHECK(std::pow(gsv::rotation_radius_growth_per_step(gsv::kIntegrators[m], h), steps) == Approx(expected[m]).epsilon(1e-13));
        const StepSpec spec{ParticleScene::Rotation, gsv::kIntegrators[m], h};
        const glm::dvec3 start(0.5, 0, 0);
        const double ratio = glm::length(run<double>(spec, start, {0, 0.5, 0}, steps)) / 0.5;
        CHECK(ratio == Approx(expected[m]).epsilon(1e-12));
        const float ratio_f = glm::length(run<float>(spec, glm::vec3(start), {0, 0.5f, 0}, steps)) / 0.5f;
        CHECK(ratio_f == Approx(expected[m]).epsilon(1e-5));
    }
}

TEST_CASE("particles: a particle on a stagnation point stays exactly there", "[unit][particles]") {
    for (ParticleScene scene : {ParticleScene::Rotation, ParticleScene::Saddle})
        for (Integrator integrator : gsv::kIntegrators) {
            INFO(gsv::particle_scene_name(scene) << " " << gsv::integrator_name(integrator));
            const StepSpec spec{scene, integrator, 0.1};
            glm::dvec3 v(1.0);
            const glm::dvec3 p = run<double>(spec, glm::dvec3(0.0), glm::dvec3(0.0), 100, &v);
            CHECK(same_bits(p, glm::dvec3(0.0)));
            CHECK(v == glm::dvec3(0.0));
            glm::vec3 v_f(1.0f);
            const glm::vec3 p_f = run<float>(spec, glm::vec3(0.0f), glm::vec3(0.0f), 100, &v_f);
            CHECK(same_bits(p_f, glm::vec3(0.0f)));
            CHECK(v_f == glm::vec3(0.0f));
        }
}

TEST_CASE("particles: leaving the domain returns to the origin, while the boundary itself is inside", "[unit][particles]") {
    const auto check_both = [](const StepSpec& spec, glm::dvec3 p, glm::dvec3 v, glm::dvec3 p0, glm::dvec3 v0,
                               glm::dvec3 want_p, glm::dvec3 want_v, bool want_exit) {
        glm::dvec3 pd = p, vd = v;
        CHECK(gsv::step_particle<double>(spec, pd, vd, p0, v0) == want_exit);
        CHECK(pd == want_p);
        CHECK(vd == want_v);
        glm::vec3 pf(p), vf(v);
        CHECK(gsv::step_particle<float>(spec, pf, vf, glm::vec3(p0), glm::vec3(v0)) == want_exit);
        CHECK(pf == glm::vec3(want_p));
        CHECK(vf == glm::vec3(want_v));
    };
    const glm::dvec3 p0(0.2, 0.3, 0.4), v0(0.5, -0.25, 0.125);
    SECTION("saddle pushes a particle at x = 1 out along x") {
        // (1, 0, 0) + 0.1 (1, 0, 0) = (1.1, 0, 0).
        check_both({ParticleScene::Saddle, Integrator::Euler, 0.1}, {1, 0, 0}, {1, 0, 0}, p0, v0, p0, v0, true);
        check_both({ParticleScene::Saddle, Integrator::Rk4, 0.1}, {-1, 0.5, 0}, {-1, -0.5, 0}, p0, v0, p0, v0, true);
    }
    SECTION("rotation slides along the boundary without crossing it") {
        // (0, 1, 0) + 0.1 (-1, 0, 0): y stays exactly 1, which is not > 1.
        check_both({ParticleScene::Rotation, Integrator::Euler, 0.1}, {0, 1, 0}, {0, 0, 0}, p0, v0, {-0.1, 1, 0},
                   {-1, 0, 0}, false);
        check_both({ParticleScene::Rotation, Integrator::Euler, 0.1}, {0, -1, 0}, {0, 0, 0}, p0, v0, {0.1, -1, 0},
                   {1, 0, 0}, false);
        check_both({ParticleScene::Rotation, Integrator::Euler, 0.1}, {1, 0, 0}, {0, 0, 0}, p0, v0, {1, 0.1, 0},
                   {-0.0, 1, 0}, false);
        check_both({ParticleScene::Saddle, Integrator::Rk4, 0.1}, {0, 0, -1}, {0, 0, 0}, p0, v0, {0, 0, -1},
                   {0, 0, 0}, false);
    }
    SECTION("gravity: a fall to exactly y = -1 stays, a little further returns") {
        // Euler with h = 1/4: -0.5 + 0.25 (-2) = -1 exactly; -0.5 + 0.25 (-2.5) = -1.125.
        const StepSpec spec{ParticleScene::Gravity, Integrator::Euler, 0.25, 2};
        check_both(spec, {0, -0.5, 0}, {0, -2, 0}, p0, v0, {0, -1, 0}, {0, -2.5, 0}, false);
        check_both(spec, {0, -0.5, 0}, {0, -2.5, 0}, p0, v0, p0, v0, true);
        check_both({ParticleScene::Gravity, Integrator::Midpoint, 0.1, 2}, {0, -0.95, 0}, {0, -1, 0}, p0, v0, p0, v0,
                   true);
    }
}

TEST_CASE("particles: gravity's midpoint and rk4 follow the exact parabola, Euler lags by G h t / 2", "[unit][particles]") {
    const double G = 2, h = 0.01;
    const int n = 100;
    const double t = n * h;
    const glm::dvec3 p0(0.1, -0.8, -0.2), v0(0.3, 2, -0.1), g(0, -G, 0);
    const glm::dvec3 exact_p = p0 + v0 * t + g * (t * t / 2), exact_v = v0 + g * t;
    for (Integrator integrator : {Integrator::Midpoint, Integrator::Rk4}) {
        INFO(gsv::integrator_name(integrator));
        glm::dvec3 v;
        const glm::dvec3 p = run<double>({ParticleScene::Gravity, integrator, h, G}, p0, v0, n, &v);
        CHECK(glm::length(p - exact_p) < 1e-12);
        CHECK(glm::length(v - exact_v) < 1e-12);
    }
    // Euler: p_n = p0 + v0 t + g h^2 (0 + 1 + ... + n-1) = exact + g (h^2 n (n-1) - t^2) / 2 = exact - g h t / 2.
    glm::dvec3 v;
    const glm::dvec3 p = run<double>({ParticleScene::Gravity, Integrator::Euler, h, G}, p0, v0, n, &v);
    CHECK(std::abs((p.y - exact_p.y) - G * h * t / 2) < 1e-12);
    CHECK(std::abs(p.x - exact_p.x) < 1e-12);
    CHECK(std::abs(p.z - exact_p.z) < 1e-12);
    CHECK(glm::length(v - exact_v) < 1e-12);
}

// ---------------------------------------------------------------------------------------------------------
// The velocity grid

TEST_CASE("particles: the grid holds the field at texel centres, x fastest", "[unit][particles]") {
    const int n = 5;
    const VelocityGrid grid = VelocityGrid::sample(ParticleScene::Abc, n);
    REQUIRE(grid.n == n);
    REQUIRE(grid.texels.size() == 3u * n * n * n);
    const auto centre = [](int i) { return -1.0 + (2.0 * i + 1.0) / 5.0; };
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec3 at_centre(centre(i), centre(j), centre(k));
                const glm::vec3 want(gsv::field_velocity<double>(ParticleScene::Abc, at_centre));
                const std::size_t at = 3 * static_cast<std::size_t>((k * n + j) * n + i);
                CHECK(same_bits(glm::vec3(grid.texels[at], grid.texels[at + 1], grid.texels[at + 2]), want));
                CHECK(same_bits(grid.texel(i, j, k), want));
            }
}

TEST_CASE("particles: grid lookup gives texels at centres, the trilinear mix between, the edge beyond", "[unit][particles]") {
    // A power-of-two side: texel centres and these fractions are exact in binary.
    const int n = 16;
    const VelocityGrid grid = VelocityGrid::sample(ParticleScene::Abc, n);
    const auto position = [](double texel_coordinate) { return (texel_coordinate + 0.5) / 16 * 2 - 1; };
    for (int i : {0, 3, 15})
        for (int j : {0, 7, 15})
            for (int k : {0, 9, 15}) {
                const glm::dvec3 got = grid_lookup(grid, glm::dvec3(position(i), position(j), position(k)));
                CHECK(got == glm::dvec3(grid.texel(i, j, k)));
                CHECK(grid_lookup(grid, glm::vec3(position(i), position(j), position(k))) == grid.texel(i, j, k));
            }

    // Between centres: the weighted sum of the eight neighbours.
    const glm::dvec3 x(4.25, 10.5, 6.875);  // texel coordinates
    const glm::dvec3 p(position(x.x), position(x.y), position(x.z));
    const glm::ivec3 i0 = glm::ivec3(glm::floor(x));
    const glm::dvec3 f = x - glm::floor(x);
    glm::dvec3 want(0.0);
    for (int c = 0; c < 8; ++c) {
        const glm::ivec3 corner((c & 1), (c >> 1) & 1, (c >> 2) & 1);
        const double weight = (corner.x ? f.x : 1 - f.x) * (corner.y ? f.y : 1 - f.y) * (corner.z ? f.z : 1 - f.z);
        want += weight * glm::dvec3(grid.texel(i0.x + corner.x, i0.y + corner.y, i0.z + corner.z));
    }
    const glm::dvec3 got = grid_lookup(grid, p);
    for (int a = 0; a < 3; ++a) CHECK(got[a] == Approx(want[a]).epsilon(1e-14).margin(1e-15));
    const glm::vec3 got_f = grid_lookup(grid, glm::vec3(p));
    for (int a = 0; a < 3; ++a) CHECK(got_f[a] == Approx(want[a]).margin(1e-6));

    // Clamped: the outer half texel and beyond take the edge texels.
    CHECK(grid_lookup(grid, glm::dvec3(1, 1, 1)) == glm::dvec3(grid.texel(15, 15, 15)));
    CHECK(grid_lookup(grid, glm::dvec3(-1, -1, -1)) == glm::dvec3(grid.texel(0, 0, 0)));
    CHECK(grid_lookup(grid, glm::dvec3(7, -3, position(9))) == glm::dvec3(grid.texel(15, 0, 9)));
    CHECK(grid_lookup(grid, glm::vec3(1, 1, 1)) == grid.texel(15, 15, 15));

    // Trilinear interpolation of a linear field is the field itself, between the outermost centres.
    const VelocityGrid linear = VelocityGrid::sample(ParticleScene::Rotation, n);
    for (const glm::dvec3& q : inner_points(50, 0.9, 3)) {
        const glm::dvec3 exact = gsv::field_velocity<double>(ParticleScene::Rotation, q);
        CHECK(glm::length(grid_lookup(linear, q) - exact) < 1e-14);
    }
}

TEST_CASE("particles: integrating through a finer grid comes closer to the analytic path", "[unit][particles]") {
    const std::vector<glm::dvec3> starts = inner_points(64, 0.7, 11);
    const ParticleSet set = field_set(ParticleScene::Abc, starts);
    const StepSpec analytic{ParticleScene::Abc, Integrator::Rk4, 0.01};
    const gsv::ReferenceRun exact = gsv::advance_reference(set, all_indices(set.count()), analytic, 10, 1);
    double error[2];
    const int sides[2] = {8, 64};
    for (int s = 0; s < 2; ++s) {
        const VelocityGrid grid = VelocityGrid::sample(ParticleScene::Abc, sides[s]);
        StepSpec through_grid = analytic;
        through_grid.grid = &grid;
        const gsv::ReferenceRun run = gsv::advance_reference(set, all_indices(set.count()), through_grid, 10, 1);
        CHECK(none_exited(run));
        error[s] = rms_distance(run.positions, exact.positions);
    }
    INFO("rms error, n = 8: " << error[0] << ", n = 64: " << error[1]);
    CHECK(error[1] < 1e-3);
    // Trilinear interpolation is second order: 8x finer should be ~64x closer; ask for much less.
    CHECK(error[1] * 16 < error[0]);
    CHECK(none_exited(exact));
}

// ---------------------------------------------------------------------------------------------------------
// Orders of accuracy against the converged reference

TEST_CASE("particles: abc errors fall with each integrator's order as h halves", "[unit][particles]") {
    // Starts within 0.3 of the centre and a time of 0.8: speeds are below 0.9 per axis, so nobody can leave.
    const ParticleSet set = field_set(ParticleScene::Abc, inner_points(32, 0.3, 5));
    const std::vector<std::size_t> indices = all_indices(set.count());
    const double time = 0.8, coarsest = 0.1;
    const gsv::ReferenceRun converged =
        gsv::advance_reference(set, indices, {ParticleScene::Abc, Integrator::Rk4, coarsest / 4}, 32, 64);
    REQUIRE(none_exited(converged));
    struct Expected {
        Integrator integrator;
        double low, high;
    };
    for (const Expected& e : {Expected{Integrator::Euler, 1.6, 2.5}, Expected{Integrator::Midpoint, 3, 5},
                              Expected{Integrator::Rk4, 12, 20}}) {
        double error[3];
        for (int level = 0; level < 3; ++level) {
            const double h = coarsest / (1 << level);
            const gsv::ReferenceRun run = gsv::advance_reference(
                set, indices, {ParticleScene::Abc, e.integrator, h}, static_cast<int>(std::lround(time / h)), 1);
            CHECK(none_exited(run));
            error[level] = rms_distance(run.positions, converged.positions);
        }
        INFO(gsv::integrator_name(e.integrator) << " rms errors " << error[0] << " " << error[1] << " " << error[2]);
        CHECK(error[0] / error[1] >= e.low);
        CHECK(error[0] / error[1] <= e.high);
        CHECK(error[1] / error[2] >= e.low);
        CHECK(error[1] / error[2] <= e.high);
    }
}

// ---------------------------------------------------------------------------------------------------------
// The multi-threaded CPU update

TEST_CASE("particles: advance_cpu is bit-identical for any thread count and leaves the sentinels alone",
          "[unit][particles]") {
    const std::size_t count = 10007, capacity = 10240;
    for (ParticleScene scene : {ParticleScene::Abc, ParticleScene::Gravity}) {
        INFO(gsv::particle_scene_name(scene));
        const ParticleSet start = gsv::pad_particles(gsv::make_particles(scene, count, 42), capacity);
        const StepSpec spec{scene, Integrator::Rk4, 0.02};
        ParticleSet first = start;
        gsv::advance_cpu(first, count, spec, 30, 1);
        CHECK_FALSE(same_bits(first.positions, start.positions));  // it did move them
        for (int threads : {2, 3, 7}) {
            INFO(threads << " threads");
            ParticleSet other = start;
            gsv::advance_cpu(other, count, spec, 30, threads);
            CHECK(same_bits(other.positions, first.positions));
            CHECK(same_bits(other.velocities, first.velocities));
        }
        bool sentinels_untouched = true, w_kept = true;
        for (std::size_t i = 0; i < capacity; ++i) {
            if (i >= count)
                sentinels_untouched = sentinels_untouched && same_bits(first.positions[i], start.positions[i]) &&
                                      same_bits(first.velocities[i], start.velocities[i]);
            w_kept = w_kept && first.positions[i].w == start.positions[i].w &&
                     first.velocities[i].w == start.velocities[i].w;
        }
        CHECK(sentinels_untouched);
        CHECK(w_kept);
        CHECK(same_bits(first.origins.data()[0], start.origins.data()[0]));
    }
}

TEST_CASE("particles: advance_cpu in float agrees with the double reference of the same method", "[unit][particles]") {
    const std::size_t count = 10007;
    for (ParticleScene scene : {ParticleScene::Abc, ParticleScene::Gravity, ParticleScene::Saddle})
        for (Integrator integrator : gsv::kIntegrators) {
            INFO(gsv::particle_scene_name(scene) << " " << gsv::integrator_name(integrator));
            ParticleSet set = gsv::make_particles(scene, count, 9);
            const StepSpec spec{scene, integrator, 0.01};
            const std::vector<std::size_t> sample = gsv::reference_sample(count, 512);
            const gsv::ReferenceRun reference = gsv::advance_reference(set, sample, spec, 5, 1);
            gsv::advance_cpu(set, count, spec, 5);
            double worst = 0;
            for (std::size_t m = 0; m < sample.size(); ++m)
                worst = std::max(worst, glm::distance(glm::dvec3(glm::vec3(set.positions[sample[m]])),
                                                      reference.positions[m]));
            INFO("largest distance " << worst);
            CHECK(worst < 1e-5);
        }
}

TEST_CASE("particles: advance_cpu with a grid matches step_particle through the same grid", "[unit][particles]") {
    const VelocityGrid grid = VelocityGrid::sample(ParticleScene::Abc, 12);
    StepSpec spec{ParticleScene::Abc, Integrator::Midpoint, 0.05};
    spec.grid = &grid;
    ParticleSet set = gsv::make_particles(ParticleScene::Abc, 100, 1);
    const ParticleSet start = set;
    gsv::advance_cpu(set, set.count(), spec, 7, 2);
    for (std::size_t i = 0; i < set.count(); ++i) {
        const gsv::ParticleOrigin& origin = start.origins[i];
        const glm::vec3 p = run<float>(spec, glm::vec3(origin.position), glm::vec3(origin.velocity), 7);
        CHECK(same_bits(glm::vec3(set.positions[i]), p));
    }
}

// ---------------------------------------------------------------------------------------------------------
// Initial sets and small helpers

TEST_CASE("particles: make_particles is deterministic for a seed and inside the domain", "[unit][particles]") {
    for (ParticleScene scene : gsv::kParticleScenes) {
        INFO(gsv::particle_scene_name(scene));
        const ParticleSet a = gsv::make_particles(scene, 1000, 7), b = gsv::make_particles(scene, 1000, 7);
        const ParticleSet other = gsv::make_particles(scene, 1000, 8), prefix = gsv::make_particles(scene, 100, 7);
        REQUIRE(a.count() == 1000);
        CHECK(same_bits(a.positions, b.positions));
        CHECK(same_bits(a.velocities, b.velocities));
        CHECK(same_bits(a.origins, b.origins));
        CHECK_FALSE(same_bits(a.positions, other.positions));
        CHECK(same_bits(prefix.positions, std::vector<glm::vec4>(a.positions.begin(), a.positions.begin() + 100)));
        CHECK(same_bits(prefix.velocities, std::vector<glm::vec4>(a.velocities.begin(), a.velocities.begin() + 100)));

        bool inside = true, w_right = true, origins_right = true, velocities_right = true;
        for (std::size_t i = 0; i < a.count(); ++i) {
            const glm::vec3 p(a.positions[i]), v(a.velocities[i]);
            inside = inside && glm::all(glm::lessThanEqual(glm::abs(p), glm::vec3(1)));
            w_right = w_right && a.positions[i].w == 1 && a.velocities[i].w == 0;
            if (scene == ParticleScene::Gravity) {
                // Launched from the nozzle, and started somewhere along the exact parabola of that launch.
                const glm::dvec3 p0(a.origins[i].position), v0(a.origins[i].velocity);
                const glm::vec3 jitter = glm::vec3(p0) - glm::vec3(0, -0.8f, 0);
                const bool near_nozzle = glm::all(glm::lessThanEqual(glm::abs(jitter), glm::vec3(0.05f + 1e-6f)));
                velocities_right = velocities_right && near_nozzle && std::abs(v0.x) <= 0.35f &&
                                   std::abs(v0.z) <= 0.35f && v0.y >= 1.6f && v0.y <= 2.4f;
                const double tau = (v0.y - double(v.y)) / 2.0;  // G = 2: the time into the flight
                const glm::dvec3 along = p0 + tau * v0 + (tau * tau / 2.0) * glm::dvec3(0, -2, 0);
                origins_right = origins_right && tau >= -1e-6 && tau <= 2 * v0.y / 2.0 + 1e-6 &&
                                glm::length(along - glm::dvec3(p)) < 1e-5 && std::abs(v.x - v0.x) < 1e-6;
            } else {
                origins_right = origins_right && same_bits(a.origins[i].position, a.positions[i]) &&
                                same_bits(a.origins[i].velocity, a.velocities[i]);
                velocities_right = velocities_right &&
                                   same_bits(v, glm::vec3(gsv::field_velocity<double>(scene, glm::dvec3(p))));
            }
        }
        CHECK(inside);
        CHECK(w_right);
        CHECK(origins_right);
        CHECK(velocities_right);
    }
}

TEST_CASE("particles: pad_particles fills the capacity with undrawn sentinels", "[unit][particles]") {
    const ParticleSet set = gsv::make_particles(ParticleScene::Rotation, 1000, 3);
    const ParticleSet padded = gsv::pad_particles(set, 1024);
    REQUIRE(padded.count() == 1024);
    REQUIRE(padded.velocities.size() == 1024);
    REQUIRE(padded.origins.size() == 1024);
    CHECK(same_bits(std::vector<glm::vec4>(padded.positions.begin(), padded.positions.begin() + 1000), set.positions));
    for (std::size_t i = 1000; i < 1024; ++i) {
        CHECK(padded.positions[i] == glm::vec4(0.3f, 0.6f, 0.2f, 0.0f));
        CHECK(padded.origins[i].position == glm::vec4(0.3f, 0.6f, 0.2f, 0.0f));
        CHECK(padded.velocities[i] == glm::vec4(0.0f));
        CHECK(padded.origins[i].velocity == glm::vec4(0.0f));
    }
    CHECK(gsv::pad_particles(set, 1000).count() == 1000);
    CHECK(contains(gsv_error_message([&] { gsv::pad_particles(set, 999); }), "999"));
}

TEST_CASE("particles: reference_sample spreads at most the asked number of indices evenly", "[unit][particles]") {
    CHECK(gsv::reference_sample(5, 4096) == std::vector<std::size_t>{0, 1, 2, 3, 4});
    CHECK(gsv::reference_sample(10, 4) == std::vector<std::size_t>{0, 2, 5, 7});
    CHECK(gsv::reference_sample(10, 0).empty());
    const std::vector<std::size_t> big = gsv::reference_sample(std::size_t(1) << 40, 4096);
    REQUIRE(big.size() == 4096);
    CHECK(big[1] == std::size_t(1) << 28);
    CHECK(big.back() == (std::size_t(1) << 40) - (std::size_t(1) << 28));
    CHECK(std::is_sorted(big.begin(), big.end()));
}

TEST_CASE("particles: bandwidth is positive and finite, and traffic per step is as documented", "[unit][particles]") {
    const double rate = gsv::measure_copy_bandwidth(1 << 16, 3);
    CHECK(std::isfinite(rate));
    CHECK(rate > 0);
    CHECK(gsv::bytes_per_particle_step({ParticleScene::Abc, Integrator::Rk4, 0.01}) == 64);
    CHECK(gsv::bytes_per_particle_step({ParticleScene::Rotation, Integrator::Euler, 0.01}) == 64);
    CHECK(gsv::bytes_per_particle_step({ParticleScene::Gravity, Integrator::Euler, 0.01}) == 80);
}

TEST_CASE("particles: names round-trip and bad input is refused naming the value", "[unit][particles]") {
    for (ParticleScene scene : gsv::kParticleScenes)
        CHECK(gsv::particle_scene_from_name(gsv::particle_scene_name(scene)) == scene);
    for (Integrator integrator : gsv::kIntegrators)
        CHECK(gsv::integrator_from_name(gsv::integrator_name(integrator)) == integrator);

    const std::string scene = gsv_error_message([] { gsv::particle_scene_from_name("vortex"); });
    CHECK(contains(scene, "'vortex'"));
    CHECK(contains(scene, "gravity, rotation, saddle, abc"));
    const std::string integrator = gsv_error_message([] { gsv::integrator_from_name("rk5"); });
    CHECK(contains(integrator, "'rk5'"));
    CHECK(contains(integrator, "euler, midpoint, rk4"));
    CHECK(contains(gsv_error_message([] { VelocityGrid::sample(ParticleScene::Abc, 1); }), "side 1 "));
    CHECK(contains(gsv_error_message([] { VelocityGrid::sample(ParticleScene::Abc, 513); }), "side 513 "));
    CHECK(contains(gsv_error_message([] { VelocityGrid::sample(ParticleScene::Gravity, 8); }), "gravity"));
    CHECK(contains(gsv_error_message([] { gsv::field_velocity<double>(ParticleScene::Gravity, glm::dvec3(0.0)); }),
                   "gravity"));
    CHECK(contains(gsv_error_message([] { gsv::field_velocity<float>(ParticleScene::Gravity, glm::vec3(0.0f)); }),
                   "gravity"));

    ParticleSet set = gsv::make_particles(ParticleScene::Abc, 10, 1);
    const StepSpec good{ParticleScene::Abc, Integrator::Rk4, 0.01};
    CHECK(contains(gsv_error_message([&] { gsv::advance_cpu(set, 11, good, 1); }), "count 11"));
    CHECK(contains(gsv_error_message([&] { gsv::advance_cpu(set, 10, good, -1); }), "steps = -1"));
    CHECK(contains(gsv_error_message([&] { gsv::advance_cpu(set, 10, good, 1, -2); }), "threads = -2"));
    const StepSpec no_step{ParticleScene::Abc, Integrator::Rk4, std::numeric_limits<double>::quiet_NaN()};
    CHECK(contains(gsv_error_message([&] { gsv::advance_cpu(set, 10, no_step, 1); }), "h = nan"));
    const VelocityGrid grid = VelocityGrid::sample(ParticleScene::Abc, 4);
    StepSpec gravity_with_grid{ParticleScene::Gravity, Integrator::Euler, 0.01};
    gravity_with_grid.grid = &grid;
    CHECK(contains(gsv_error_message([&] { gsv::advance_cpu(set, 10, gravity_with_grid, 1); }), "gravity"));
    VelocityGrid broken = grid;
    broken.texels.pop_back();
    StepSpec broken_grid = good;
    broken_grid.grid = &broken;
    CHECK(contains(gsv_error_message([&] { gsv::advance_cpu(set, 10, broken_grid, 1); }), "191 floats for side 4"));
    const StepSpec no_scene{static_cast<ParticleScene>(9), Integrator::Rk4, 0.01};
    CHECK(contains(gsv_error_message([&] { gsv::advance_cpu(set, 10, no_scene, 1); }), "scene 9"));
    const double infinite = std::numeric_limits<double>::infinity();
    CHECK(contains(gsv_error_message([&] { gsv::make_particles(ParticleScene::Gravity, 1, 1, infinite); }),
                   "gravity = inf"));
    CHECK(contains(gsv_error_message([&] { gsv::advance_reference(set, {3, 10}, good, 1, 1); }), "index 10"));
    CHECK(contains(gsv_error_message([&] { gsv::advance_reference(set, {3}, good, 1, 0); }), "substeps = 0"));
    CHECK(contains(gsv_error_message([] { gsv::measure_copy_bandwidth(0); }), "bytes"));
    set.origins.pop_back();
    CHECK(contains(gsv_error_message([&] { gsv::advance_cpu(set, 9, good, 1); }), "9 origins"));
}
