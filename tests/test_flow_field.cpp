#include "catch.hpp"

#include "common/core/error.h"
#include "support/flow/flow_field.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <utility>
#include <limits>
#include <string>
#include <vector>

using gsv::FlowField;
using gsv::FlowKind;
using gsv::test::gsv_error_message;
using gsv::test::TempDir;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool all_finite(const FlowField& field) {
    for (float v : field.velocity)
        if (!std::isfinite(v)) return false;
    return true;
}

bool all_zero(const FlowField& field) {
    for (float v : field.velocity)
        if (v != 0.0f) return false;
    return true;
}

// Texel centre on [-1, 1], as the fields on [-1,1]^2 sample it.
double centred(int i, int n) { return (2.0 * i + 1.0 - n) / n; }

// Velocity of texel (x, y) back in domain units of [-1,1]^2 (one unit is n/2 texels).
glm::dvec2 domain_velocity(const FlowField& field, int x, int y) {
    const glm::vec2 v = field.at(x, y);
    return {v.x * 2.0 / field.width, v.y * 2.0 / field.height};
}

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Little-endian bytes of a float, assembled by hand so the test does not share the loader's code.
std::string le(float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, 4);
    std::string bytes;
    for (int i = 0; i < 4; ++i) bytes += static_cast<char>((bits >> (8 * i)) & 0xff);
    return bytes;
}

std::string floats(int count, float value) {
    std::string bytes;
    for (int i = 0; i < count; ++i) bytes += le(value);
    return bytes;
}

}  // namespace

TEST_CASE("flow kinds have names and unknown names list the valid ones", "[unit][flow]") {
    for (FlowKind kind : {FlowKind::Rotation, FlowKind::Saddle, FlowKind::Source, FlowKind::DoubleGyre,
                          FlowKind::Vortices})
        CHECK(gsv::flow_kind_from_name(gsv::flow_kind_name(kind)) == kind);
    CHECK(std::string(gsv::flow_kind_name(FlowKind::DoubleGyre)) == "double_gyre");
    CHECK(gsv_error_message([] { gsv::flow_kind_from_name("gyre"); }) ==
          "unknown flow 'gyre' (known: rotation, saddle, source, double_gyre, vortices)");
}

TEST_CASE("rotation is tangent to circles about the centre and scaled to the requested speed", "[unit][flow]") {
    for (auto [width, height] : {std::pair{64, 64}, std::pair{80, 48}}) {
        const FlowField field = gsv::make_flow(FlowKind::Rotation, width, height, 1.5);
        INFO(width << "x" << height);
        REQUIRE(field.velocity.size() == static_cast<std::size_t>(2 * width * height));
        CHECK(std::abs(field.max_speed() - 1.5f) <= 1.5f * 1e-6f);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const glm::dvec2 p(centred(x, width), centred(y, height));
                const glm::dvec2 v = domain_velocity(field, x, y);
                // Tangent in the domain, where the streamlines are circles, even on a non-square grid.
                REQUIRE(std::abs(glm::dot(v, p)) <= 1e-6 * glm::length(v) * glm::length(p));
                REQUIRE(cross(p, v) > 0.0);  // counter-clockwise
            }
    }
}

TEST_CASE("the centre texel of an odd-sized field is exactly still", "[unit][flow]") {
    for (FlowKind kind : {FlowKind::Rotation, FlowKind::Source, FlowKind::Saddle}) {
        const FlowField field = gsv::make_flow(kind, 65, 33, 1.0);
        CHECK(field.at(32, 16) == glm::vec2(0.0f));
        CHECK(field.at(31, 16) != glm::vec2(0.0f));
    }
}

TEST_CASE("source points straight outward and saddle in along y, out along x", "[unit][flow]") {
    const int width = 40, height = 30;
    const FlowField source = gsv::make_flow(FlowKind::Source, width, height, 2.0);
    const FlowField saddle = gsv::make_flow(FlowKind::Saddle, width, height, 2.0);
    CHECK(std::abs(source.max_speed() - 2.0f) <= 2e-6f);
    CHECK(std::abs(saddle.max_speed() - 2.0f) <= 2e-6f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::dvec2 p(centred(x, width), centred(y, height));  // never on an axis: even sizes
            const glm::dvec2 out = domain_velocity(source, x, y);
            REQUIRE(glm::dot(out, p) > 0.0);
            REQUIRE(std::abs(cross(out, p)) <= 1e-6 * glm::length(out) * glm::length(p));
            const glm::vec2 s = saddle.at(x, y);
            REQUIRE((s.x > 0) == (p.x > 0));
            REQUIRE((s.y > 0) == (p.y < 0));
        }
    // The corners are the fastest texels of a source: all four at the requested speed.
    CHECK(std::abs(glm::length(source.at(0, 0)) - 2.0f) <= 2e-6f);
    CHECK(std::abs(glm::length(source.at(width - 1, height - 1)) - 2.0f) <= 2e-6f);
}

TEST_CASE("double gyre at t = 0 is two mirrored cells with no flow across x = 1", "[unit][flow]") {
    // At t = 0, f(x) = x, so u = -pi A sin(pi x) cos(pi y) and v = pi A cos(pi x) sin(pi y). With x -> 2 - x,
    // sin(pi x) changes sign and cos(pi x) does not: u is odd and v even about x = 1, and u = 0 on x = 1.
    const int width = 64, height = 32;
    const FlowField field = gsv::make_flow(FlowKind::DoubleGyre, width, height, 1.0, 0.0);
    REQUIRE(all_finite(field));
    const float tolerance = 1e-6f;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width / 2; ++x) {
            const glm::vec2 left = field.at(x, y), right = field.at(width - 1 - x, y);
            REQUIRE(std::abs(left.x + right.x) <= tolerance);
            REQUIRE(std::abs(left.y - right.y) <= tolerance);
        }
    // The left cell turns clockwise (rightward along its top), the right one counter-clockwise.
    CHECK(field.at(width / 4, height - 2).x > 0.1f);
    CHECK(field.at(width / 4, 1).x < -0.1f);
    CHECK(field.at(3 * width / 4, height - 2).x < -0.1f);

    const FlowField odd = gsv::make_flow(FlowKind::DoubleGyre, 65, 32, 1.0, 0.0);
    for (int y = 0; y < 32; ++y) REQUIRE(std::abs(odd.at(32, y).x) <= tolerance);  // the column at x = 1
}

TEST_CASE("double gyre velocities are carried from domain units into texels", "[unit][flow]") {
    // At t = 0 the largest |u| and |v| in domain units are both pi A. A domain unit is width/2 texels
    // across and height texels up, so on a 200x50 grid |u| reaches twice |v| in texels.
    const FlowField field = gsv::make_flow(FlowKind::DoubleGyre, 200, 50, 1.0, 0.0);
    float max_u = 0, max_v = 0;
    for (std::size_t i = 0; i < field.velocity.size(); i += 2) {
        max_u = std::max(max_u, std::abs(field.velocity[i]));
        max_v = std::max(max_v, std::abs(field.velocity[i + 1]));
    }
    CHECK(std::abs(max_u / max_v - 2.0f) < 0.02f);
}

TEST_CASE("double gyre is finite and scaled at every time, and moves with time", "[unit][flow]") {
    std::vector<FlowField> fields;
    for (double t : {0.0, 2.5, 5.0}) {
        fields.push_back(gsv::make_flow(FlowKind::DoubleGyre, 96, 48, 0.75, t));
        INFO("t = " << t);
        CHECK(all_finite(fields.back()));
        CHECK(std::abs(fields.back().max_speed() - 0.75f) <= 1e-6f);
    }
    CHECK(fields[0].velocity != fields[1].velocity);
    // Half a period later the separatrix is back at x = 1 (sin(omega t) = 0 again).
    for (std::size_t i = 0; i < fields[0].velocity.size(); ++i)
        REQUIRE(std::abs(fields[0].velocity[i] - fields[2].velocity[i]) <= 1e-6f);
}

TEST_CASE("vortices are deterministic per seed and depend on it", "[unit][flow]") {
    const FlowField a = gsv::make_flow(FlowKind::Vortices, 64, 48, 1.0, 0.0, 7);
    CHECK(all_finite(a));
    CHECK(std::abs(a.max_speed() - 1.0f) <= 1e-6f);
    CHECK(a.velocity == gsv::make_flow(FlowKind::Vortices, 64, 48, 1.0, 0.0, 7).velocity);
    CHECK(a.velocity != gsv::make_flow(FlowKind::Vortices, 64, 48, 1.0, 0.0, 8).velocity);

    bool both_signs[2] = {false, false};
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        const std::vector<gsv::Vortex> vortices = gsv::vortices_from_seed(seed);
        REQUIRE(vortices.size() == static_cast<std::size_t>(gsv::kVortexCount));
        for (const gsv::Vortex& v : vortices) {
            REQUIRE(std::abs(v.x) <= 0.8);
            REQUIRE(std::abs(v.y) <= 0.8);
            REQUIRE(v.core_radius >= 0.15);
            REQUIRE(v.core_radius <= 0.4);
            REQUIRE((v.sign == 1 || v.sign == -1));
            both_signs[v.sign > 0] = true;
        }
    }
    CHECK(both_signs[0]);
    CHECK(both_signs[1]);
}

TEST_CASE("a vortex centred exactly on a texel centre gives no NaN", "[unit][flow]") {
    // Texel (40, 20) of a 64x64 grid has its centre at (17/64, -23/64), exact in binary.
    const gsv::Vortex on_texel{17.0 / 64.0, -23.0 / 64.0, 1, 0.2};
    REQUIRE(centred(40, 64) == on_texel.x);
    REQUIRE(centred(20, 64) == on_texel.y);
    const FlowField single = gsv::make_vortex_flow({on_texel}, 64, 64, 1.0);
    REQUIRE(all_finite(single));
    CHECK(single.at(40, 20) == glm::vec2(0.0f));
    CHECK(std::abs(single.max_speed() - 1.0f) <= 1e-6f);

    // With a second vortex the texel carries exactly the other one's velocity.
    const gsv::Vortex other{-0.5, 0.5, -1, 0.3};
    const FlowField pair = gsv::make_vortex_flow({on_texel, other}, 64, 64, 1.0);
    REQUIRE(all_finite(pair));
    const glm::dvec2 expected = gsv::vortex_velocity(other, {on_texel.x, on_texel.y});
    // Same direction: the texel velocity is the domain one times 32 texels per unit and the scaling.
    const glm::dvec2 got = glm::normalize(glm::dvec2(pair.at(40, 20)));
    CHECK(std::abs(cross(got, glm::normalize(expected))) <= 1e-6);
    CHECK(glm::dot(got, expected) > 0.0);
}

TEST_CASE("a vortex's core tends to solid-body rotation without cancellation", "[unit][flow]") {
    // Centred at the origin so that the offsets below are exact.
    const gsv::Vortex vortex{0.0, 0.0, -1, 0.25};
    const double c2 = 0.25 * 0.25;
    CHECK(gsv::vortex_velocity(vortex, {0.0, 0.0}) == glm::dvec2(0.0));
    // r = 1e-9: 1 - exp(-r^2/c^2) rounds to 0 in double, so the naive formula would give a still core.
    const glm::dvec2 near = gsv::vortex_velocity(vortex, {1e-9, 0.0});
    CHECK(near.x == 0.0);
    CHECK(near.y == Approx(-1e-9 / c2).epsilon(1e-12));
    // Both sides of the switch from the series to expm1 agree with the formula to double precision.
    for (double q : {1e-8 * (1 - 1e-6), 1e-8 * (1 + 1e-6), 1e-4, 0.5, 4.0}) {
        const double r = 0.25 * std::sqrt(q);
        const double series = (1.0 - 0.5 * q + q * q / 6.0) * r / c2;
        const double closed_form = (1.0 - std::exp(-q)) / r;  // accurate once q is not tiny
        const double expected = -(q < 1e-3 ? series : closed_form);
        INFO("q = " << q);
        CHECK(gsv::vortex_velocity(vortex, {r, 0.0}).y == Approx(expected).epsilon(1e-13));
    }
}

TEST_CASE("vortex cores must be positive", "[unit][flow]") {
    CHECK(gsv_error_message([] { gsv::make_vortex_flow({gsv::Vortex{0, 0, 1, 0.0}}, 8, 8, 1.0); }) ==
          "make_vortex_flow: vortex 0 has core radius 0; it must be positive and finite");
}

TEST_CASE("photo swirl turns a disc and leaves everything beyond its radius still", "[unit][flow]") {
    const int width = 80, height = 40;
    const double cx = 0.5, cy = 0.5, radius = 0.4;
    const FlowField field = gsv::make_photo_swirl(width, height, 2.0, cx, cy, radius);
    REQUIRE(all_finite(field));
    CHECK(std::abs(field.max_speed() - 2.0f) <= 2e-6f);
    const double outer = radius * height;  // a fraction of the shorter side, in texels
    int moving = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::dvec2 d(x + 0.5 - cx * width, y + 0.5 - cy * height);
            const glm::dvec2 v(field.at(x, y));
            if (glm::length(d) >= outer) {
                REQUIRE(v == glm::dvec2(0.0));
            } else {
                REQUIRE(glm::length(v) > 0.0);
                REQUIRE(std::abs(glm::dot(v, d)) <= 1e-6 * glm::length(v) * glm::length(d));
                REQUIRE(cross(d, v) > 0.0);
                ++moving;
            }
        }
    // pi * 16^2 = 804 texels; measured on the longer side the disc would hold four times as many.
    CHECK(moving > 700);
    CHECK(moving < 900);
    // Speeds fade smoothly: just inside the rim a texel is much slower than the fastest one.
    CHECK(glm::length(field.at(width / 2 + 15, height / 2)) < 0.2f);
}

TEST_CASE("a field that is zero everywhere stays zero after scaling", "[unit][flow]") {
    // The only texel centre of a 1x1 grid is the origin, where these fields vanish.
    for (FlowKind kind : {FlowKind::Rotation, FlowKind::Saddle, FlowKind::Source}) {
        const FlowField field = gsv::make_flow(kind, 1, 1, 2.0);
        REQUIRE(field.velocity.size() == 2);
        CHECK(all_zero(field));
        CHECK(field.max_speed() == 0.0f);
    }
    CHECK(all_zero(gsv::make_photo_swirl(16, 16, 1.0, 0.5, 0.5, 0.0)));
    CHECK(all_zero(gsv::make_photo_swirl(16, 16, 1.0, 3.0, 3.0, 0.2)));  // a disc entirely off the picture
    const FlowField still = gsv::make_flow(FlowKind::DoubleGyre, 16, 8, 0.0);
    CHECK(all_zero(still));
    CHECK(all_finite(still));
}

TEST_CASE("make_flow and FlowField::at refuse bad arguments with one clear line", "[unit][flow]") {
    CHECK(gsv_error_message([] { gsv::make_flow(FlowKind::Rotation, 0, 8, 1.0); }) ==
          "make_flow: width must be 1..8192, got 0");
    CHECK(gsv_error_message([] { gsv::make_flow(FlowKind::Rotation, 8, 9000, 1.0); }) ==
          "make_flow: height must be 1..8192, got 9000");
    CHECK(gsv_error_message([] { gsv::make_flow(FlowKind::Rotation, 8, 8, -1.0); }) ==
          "make_flow: max_texels_per_step must be finite and >= 0, got -1");
    CHECK(contains(gsv_error_message([] { gsv::make_flow(FlowKind::Rotation, 8, 8, std::nan("")); }),
                   "max_texels_per_step"));
    CHECK(contains(gsv_error_message([] {
                       gsv::make_flow(FlowKind::DoubleGyre, 8, 8, 1.0, std::numeric_limits<double>::infinity());
                   }),
                   "make_flow: time must be finite"));
    CHECK(gsv_error_message([] { gsv::make_photo_swirl(8, 8, 1.0, 0.5, 0.5, -0.1); }) ==
          "make_photo_swirl: radius must be finite and >= 0, got -0.1");
    const FlowField field = gsv::make_flow(FlowKind::Rotation, 4, 3, 1.0);
    CHECK(gsv_error_message([&] { field.at(4, 0); }) == "FlowField::at: texel (4, 0) is outside the 4x3 field");
    CHECK(gsv_error_message([&] { field.at(0, -1); }) == "FlowField::at: texel (0, -1) is outside the 4x3 field");
}

TEST_CASE(".flow files are little-endian float32 after a one-line header", "[unit][flow]") {
    TempDir dir;
    FlowField field;
    field.width = 1;
    field.height = 1;
    field.velocity = {1.0f, -2.0f};
    gsv::save_flow(dir.path("one.flow"), field);
    // 1.0f is 0x3F800000 and -2.0f is 0xC0000000, least significant byte first.
    CHECK(gsv::test::read_text(dir.path("one.flow")) ==
          std::string("GSVFLOW 1 1 1\n\x00\x00\x80\x3f\x00\x00\x00\xc0", 22));
}

TEST_CASE(".flow files round-trip bit for bit", "[unit][flow]") {
    TempDir dir;
    FlowField field = gsv::make_flow(FlowKind::Vortices, 37, 23, 1.25, 0.0, 3);
    // Values a text format or a careless conversion would lose.
    field.velocity[0] = -0.0f;
    field.velocity[1] = std::numeric_limits<float>::denorm_min();
    field.velocity[2] = std::numeric_limits<float>::max();
    field.velocity[3] = -std::numeric_limits<float>::min();
    gsv::save_flow(dir.path("v.flow"), field);
    const FlowField loaded = gsv::load_flow(dir.path("v.flow"));
    CHECK(loaded.width == 37);
    CHECK(loaded.height == 23);
    REQUIRE(loaded.velocity.size() == field.velocity.size());
    CHECK(std::memcmp(loaded.velocity.data(), field.velocity.data(), field.velocity.size() * sizeof(float)) == 0);
}

TEST_CASE("load_flow names the file and the fault in one line", "[unit][flow]") {
    TempDir dir;
    const auto message = [&](const std::string& name, const std::string& content) {
        const auto path = dir.write(name, content);
        return gsv_error_message([&] { gsv::load_flow(path); });
    };
    const std::string header = "GSVFLOW 1 2 2\n";  // 2x2 texels: 32 bytes of velocities

    const std::string missing = dir.path("missing.flow").string();
    CHECK(gsv_error_message([&] { gsv::load_flow(missing); }) ==
          "cannot read flow file '" + missing + "': no such file");
    CHECK(contains(gsv_error_message([&] { gsv::load_flow(dir.path()); }), "is a directory"));

    CHECK(contains(message("empty.flow", ""), "empty.flow': file is empty"));
    CHECK(contains(message("magic.flow", "P6 2 2 255\n" + floats(8, 0.0f)),
                   "magic.flow': not a .flow file (it must start with 'GSVFLOW 1 <width> <height>')"));
    CHECK(contains(message("binary.flow", floats(8, 1.0f)), "not a .flow file"));
    CHECK(contains(message("version.flow", "GSVFLOW 2 2 2\n" + floats(8, 0.0f)),
                   "version.flow': unsupported version '2' (this kit reads version 1)"));
    CHECK(contains(message("fields.flow", "GSVFLOW 1 2\n" + floats(8, 0.0f)),
                   "header 'GSVFLOW 1 2' is not 'GSVFLOW 1 <width> <height>'"));
    CHECK(contains(message("nonewline.flow", "GSVFLOW 1 2 2" + std::string(80, ' ')), "no newline"));

    CHECK(contains(message("zero.flow", "GSVFLOW 1 0 2\n"), "zero.flow': width '0' is not in 1..8192"));
    CHECK(contains(message("huge.flow", "GSVFLOW 1 2 8193\n"), "height '8193' is not in 1..8192"));
    CHECK(contains(message("negative.flow", "GSVFLOW 1 -2 2\n"), "width '-2' is not in 1..8192"));
    CHECK(contains(message("word.flow", "GSVFLOW 1 two 2\n"), "width 'two' is not in 1..8192"));

    CHECK(contains(message("truncated.flow", header + floats(5, 0.5f)),
                   "truncated.flow': expected 32 bytes of velocities, found 20"));
    CHECK(contains(message("headeronly.flow", header), "expected 32 bytes of velocities, found 0"));
    CHECK(contains(message("trailing.flow", header + floats(8, 0.5f) + "abc"),
                   "trailing.flow': 3 trailing bytes after the 32 bytes of velocities"));

    // Value 7 is vy of texel 3, which is (1, 1) on a 2x2 grid.
    CHECK(contains(message("nan.flow", header + floats(7, 0.5f) + le(std::nanf(""))),
                   "nan.flow': vy at texel (1, 1) is NaN"));
    CHECK(contains(message("inf.flow", header + floats(2, 0.5f) + le(-std::numeric_limits<float>::infinity()) +
                                           floats(5, 0.5f)),
                   "vx at texel (1, 0) is infinite"));

    // Each message is one line.
    CHECK(!contains(message("one_line.flow", "GSVFLOW 1 2 2\n\n\n"), "\n"));
}

TEST_CASE("save_flow refuses fields load_flow would refuse", "[unit][flow]") {
    TempDir dir;
    FlowField field;
    field.width = 2;
    field.height = 2;
    field.velocity.assign(6, 0.0f);
    CHECK(contains(gsv_error_message([&] { gsv::save_flow(dir.path("a.flow"), field); }),
                   "6 velocity values for 2x2 texels, which need 8"));
    field.velocity.assign(8, 0.0f);
    field.velocity[5] = std::numeric_limits<float>::infinity();
    CHECK(contains(gsv_error_message([&] { gsv::save_flow(dir.path("b.flow"), field); }),
                   "vy at texel (0, 1) is infinite"));
    field.width = 0;
    CHECK(contains(gsv_error_message([&] { gsv::save_flow(dir.path("c.flow"), field); }), "size 0x2 is not in 1..8192"));
    CHECK(contains(gsv_error_message([&] { gsv::save_flow(dir.path("no/such/dir/d.flow"), FlowField{1, 1, {0.0f, 0.0f}}); }),
                   "cannot write flow file"));
}

// Time-varying flows: sequences, their files, the vortex street and the double gyre over time.

namespace {

// A sequence of `frames` frames of width x height whose values are all distinct, so a frame or texel in the
// wrong place shows.
gsv::FlowSequence numbered_sequence(int width, int height, int frames) {
    gsv::FlowSequence sequence{width, height, {}};
    float next = 0.0f;
    for (int f = 0; f < frames; ++f) {
        FlowField frame{width, height, {}};
        for (int i = 0; i < 2 * width * height; ++i) frame.velocity.push_back(next += 0.25f);
        sequence.frames.push_back(frame);
    }
    return sequence;
}

std::filesystem::path committed_flow(const std::string& name) {
#ifdef GSV_SOURCE_ROOT
    return std::filesystem::path(GSV_SOURCE_ROOT) / "data" / "flows" / name;
#else
    return std::filesystem::path(__FILE__).parent_path().parent_path() / "data" / "flows" / name;
#endif
}

// The vortex street's domain velocity at the centre of texel (x, y) of a width x height grid on [0,2]x[0,1],
// carried into texels as make_vortex_street does (2 units across, 1 up).
glm::dvec2 street_texel_velocity(int x, int y, int width, int height, double phase) {
    const glm::dvec2 p((2.0 * x + 1.0) / width, (2.0 * y + 1.0) / (2.0 * height));
    const glm::dvec2 v = gsv::vortex_street_velocity(p, phase);
    return {v.x * 0.5 * width, v.y * height};
}

}  // namespace

TEST_CASE("sequences are frames after a four-field header and round-trip bit for bit", "[unit][flow]") {
    TempDir dir;
    gsv::FlowSequence sequence = numbered_sequence(3, 2, 4);
    sequence.frames[2].velocity[5] = -0.0f;
    sequence.frames[3].velocity[0] = std::numeric_limits<float>::denorm_min();
    gsv::save_flow_sequence(dir.path("s.flow"), sequence);
    const std::string bytes = gsv::test::read_text(dir.path("s.flow"));
    CHECK(bytes.substr(0, 16) == "GSVFLOW 1 3 2 4\n");
    REQUIRE(bytes.size() == 16 + 4 * 3 * 2 * 8);
    // Frame after frame: frame 1 starts right after frame 0's 12 values.
    CHECK(bytes.substr(16 + 12 * 4, 4) == le(sequence.frames[1].velocity[0]));

    const gsv::FlowSequence loaded = gsv::load_flow_sequence(dir.path("s.flow"));
    CHECK(loaded.width == 3);
    CHECK(loaded.height == 2);
    REQUIRE(loaded.frames.size() == 4);
    for (std::size_t f = 0; f < 4; ++f) {
        CHECK(loaded.frames[f].width == 3);
        CHECK(loaded.frames[f].height == 2);
        REQUIRE(loaded.frames[f].velocity.size() == 12);
        const std::size_t bytes = 12 * sizeof(float);  // bit for bit: -0.0f and denormals too
        CHECK(std::memcmp(loaded.frames[f].velocity.data(), sequence.frames[f].velocity.data(), bytes) == 0);
    }
    CHECK(loaded.max_speed() == sequence.frames[3].max_speed());
    CHECK(gsv::FlowSequence{}.max_speed() == 0.0f);

    // Even one frame gets the four-field header, and load_flow still reads it.
    gsv::save_flow_sequence(dir.path("one.flow"), numbered_sequence(1, 1, 1));
    CHECK(gsv::test::read_text(dir.path("one.flow")).substr(0, 16) == "GSVFLOW 1 1 1 1\n");
    CHECK(gsv::load_flow(dir.path("one.flow")).velocity == std::vector<float>{0.25f, 0.5f});
}

TEST_CASE("one-frame files read both ways, and load_flow refuses a sequence in one line", "[unit][flow]") {
    TempDir dir;
    const auto single = dir.write("single.flow", "GSVFLOW 1 1 1\n" + le(1.0f) + le(2.0f));
    const auto four = dir.write("four.flow", "GSVFLOW 1 1 1 1\n" + le(1.0f) + le(2.0f));
    CHECK(gsv::load_flow(single).velocity == std::vector<float>{1.0f, 2.0f});
    CHECK(gsv::load_flow(four).velocity == std::vector<float>{1.0f, 2.0f});
    const gsv::FlowSequence as_sequence = gsv::load_flow_sequence(single);
    REQUIRE(as_sequence.frames.size() == 1);
    CHECK(as_sequence.frames[0].velocity == std::vector<float>{1.0f, 2.0f});

    const auto three = dir.write("three.flow", "GSVFLOW 1 2 2 3\n" + floats(24, 0.5f));
    CHECK(gsv_error_message([&] { gsv::load_flow(three); }) ==
          "flow file '" + three.string() + "': holds 3 frames; a single field is needed (lab 03 reads sequences)");
    CHECK(gsv::load_flow_sequence(three).frames.size() == 3);
}

TEST_CASE("load_flow_sequence names the frame and the fault in one line", "[unit][flow]") {
    TempDir dir;
    const auto message = [&](const std::string& name, const std::string& content) {
        const auto path = dir.write(name, content);
        return gsv_error_message([&] { gsv::load_flow_sequence(path); });
    };
    const std::string header = "GSVFLOW 1 2 2 3\n";  // 3 frames of 2x2 texels: 32 bytes each, 96 in all

    CHECK(contains(message("zero.flow", "GSVFLOW 1 2 2 0\n"), "zero.flow': frames '0' is not in 1..4096"));
    CHECK(contains(message("many.flow", "GSVFLOW 1 2 2 5000\n"), "frames '5000' is not in 1..4096"));
    CHECK(contains(message("word.flow", "GSVFLOW 1 2 2 three\n"), "frames 'three' is not in 1..4096"));
    CHECK(contains(message("fields.flow", "GSVFLOW 1 2 2 3 4\n"),
                   "header 'GSVFLOW 1 2 2 3 4' is not 'GSVFLOW 1 <width> <height>' or "
                   "'GSVFLOW 1 <width> <height> <frames>'"));
    // 16 frames of 8192x8192 would be 8 GiB: refused from the header alone, before any allocation.
    CHECK(contains(message("big.flow", "GSVFLOW 1 8192 8192 16\n" + floats(8, 0.0f)),
                   "big.flow': 16 frames of 8192x8192 texels need 8589934592 bytes of velocities, more than the "
                   "1073741824 (1 GiB) a .flow file may hold"));

    CHECK(contains(message("cut2.flow", header + floats(2 * 8 + 3, 0.5f)),
                   "cut2.flow': expected 96 bytes of velocities for 3 frames, found 76: they end in frame 2, after "
                   "12 of its 32 bytes (frames count from 0; 2x2 texels, 8 bytes each)"));
    CHECK(contains(message("before2.flow", header + floats(2 * 8, 0.5f)),
                   "expected 96 bytes of velocities for 3 frames, found 64: they end before frame 2 "));
    CHECK(contains(message("trailing.flow", header + floats(24, 0.5f) + "x"),
                   "1 trailing bytes after the 96 bytes of velocities"));

    // Value 5 of frame 1 is vy of texel 2, which is (0, 1) on a 2x2 grid.
    CHECK(contains(message("nan.flow", header + floats(8 + 5, 0.5f) + le(std::nanf("")) + floats(10, 0.5f)),
                   "nan.flow': vy at texel (0, 1) of frame 1 is NaN"));
    CHECK(contains(message("inf.flow", header + floats(16, 0.5f) + le(std::numeric_limits<float>::infinity()) +
                                           floats(7, 0.5f)),
                   "vx at texel (0, 0) of frame 2 is infinite"));
    CHECK(!contains(message("one_line.flow", header + "\n\n"), "\n"));
}

TEST_CASE("save_flow_sequence refuses sequences load_flow_sequence would refuse, before writing", "[unit][flow]") {
    TempDir dir;
    const auto refusal = [&](const gsv::FlowSequence& sequence) {
        const std::string message = gsv_error_message([&] { gsv::save_flow_sequence(dir.path("s.flow"), sequence); });
        CHECK(!std::filesystem::exists(dir.path("s.flow")));
        return message;
    };
    gsv::FlowSequence sequence = numbered_sequence(2, 2, 3);
    sequence.frames[2] = numbered_sequence(4, 2, 1).frames[0];
    CHECK(refusal(sequence) == "save_flow_sequence '" + dir.path("s.flow").string() +
                                   "': frame 2 is 4x2, not the sequence's 2x2");
    sequence = numbered_sequence(2, 2, 3);
    sequence.frames[1].velocity.pop_back();
    CHECK(contains(refusal(sequence), "frame 1 has 7 velocity values for 2x2 texels, which need 8"));
    sequence = numbered_sequence(2, 2, 3);
    sequence.frames[1].velocity[3] = -std::numeric_limits<float>::infinity();
    CHECK(contains(refusal(sequence), "vy at texel (1, 0) of frame 1 is infinite"));
    CHECK(contains(refusal(gsv::FlowSequence{2, 2, {}}), "holds 0 frames; a .flow file holds 1..4096"));
    CHECK(contains(refusal(gsv::FlowSequence{0, 2, {}}), "holds 0 frames"));
    CHECK(contains(refusal(gsv::FlowSequence{0, 2, {FlowField{0, 2, {}}}}), "size 0x2 is not in 1..8192 each way"));
    // 2 frames of 8192x8192 are exactly 1 GiB; 3 are over, refused before the missing velocities are looked at.
    const gsv::FlowSequence huge{8192, 8192, std::vector<FlowField>(3)};
    CHECK(contains(refusal(huge), "3 frames of 8192x8192 texels need 1610612736 bytes of velocities"));
}

TEST_CASE("the vortex street repeats after one period and moves within it", "[unit][flow]") {
    double largest_difference = 0.0;
    for (double phase : {0.0, 0.3, 0.75})
        for (double x = 0.05; x < 2.0; x += 0.1)
            for (double y = 0.05; y < 1.0; y += 0.1) {
                const glm::dvec2 now = gsv::vortex_street_velocity({x, y}, phase);
                for (int periods : {1, 2, -1}) {
                    const glm::dvec2 later = gsv::vortex_street_velocity({x, y}, phase + periods);
                    REQUIRE(glm::length(later - now) <= 1e-6 * glm::length(now));
                }
                largest_difference = std::max(
                    largest_difference, glm::length(gsv::vortex_street_velocity({x, y}, phase + 0.5) - now));
            }
    CHECK(largest_difference > 0.1);  // the stream is 1; the vortices move by half a spacing

    // The pattern drifts one spacing (0.5, vortex_street.cpp) per period: a sixteenth of a period later the
    // flow at x + 0.5/16 is what it was at x, up to the strength ramps far outside the domain (the stream
    // is 1; the vortices reach about 1.4).
    for (double x = 0.0; x < 1.95; x += 0.05)
        for (double y = 0.0; y < 1.0; y += 0.02) {
            const glm::dvec2 before = gsv::vortex_street_velocity({x, y}, 0.2);
            const glm::dvec2 after = gsv::vortex_street_velocity({x + 0.5 / 16, y}, 0.2 + 1.0 / 16);
            REQUIRE(glm::length(after - before) <= 1e-3);
        }
    CHECK(contains(gsv_error_message([] { gsv::vortex_street_velocity({0, 0}, std::nan("")); }),
                   "vortex_street_velocity: phase must be finite"));
}

TEST_CASE("the vortex street is a stream with two rows of opposite vortices about y = 1/2", "[unit][flow]") {
    // Far above and below the street the stream dominates: everything moves right.
    for (double x = 0.0; x <= 2.0; x += 0.05) {
        CHECK(gsv::vortex_street_velocity({x, 0.02}, 0.0).x > 0.9);
        CHECK(gsv::vortex_street_velocity({x, 0.98}, 0.0).x > 0.9);
    }
    // Circulation around a small square about a vortex of each row: clockwise above, counter-clockwise below.
    // At phase 0 the upper row's vortices sit at x = -2 + 0.5 s for whole s (vortex_street.cpp), so one at
    // x = 1, and the lower row's half a spacing downstream, one at x = 1.25.
    const double half_gap = 0.5 * 0.5 * std::log(1.0 + std::sqrt(2.0)) / std::acos(-1.0);
    const auto circulation = [](glm::dvec2 c) {
        double sum = 0;
        const double r = 0.03, step = 0.001;
        for (double t = -r; t < r; t += step) {
            sum += gsv::vortex_street_velocity({c.x + t, c.y - r}, 0.0).x * step;
            sum += gsv::vortex_street_velocity({c.x + r, c.y + t}, 0.0).y * step;
            sum -= gsv::vortex_street_velocity({c.x + t, c.y + r}, 0.0).x * step;
            sum -= gsv::vortex_street_velocity({c.x - r, c.y + t}, 0.0).y * step;
        }
        return sum;
    };
    CHECK(circulation({1.0, 0.5 + half_gap}) < -0.05);
    CHECK(circulation({1.25, 0.5 - half_gap}) > 0.05);
    CHECK(std::abs(circulation({1.125, 0.5})) < 0.01);
}

TEST_CASE("make_vortex_street scales every frame by one factor to the requested top speed", "[unit][flow]") {
    const int width = 50, height = 30, frames = 5;
    const gsv::FlowSequence street = gsv::make_vortex_street(width, height, frames, 1.5);
    CHECK(street.width == width);
    CHECK(street.height == height);
    REQUIRE(street.frames.size() == static_cast<std::size_t>(frames));
    CHECK(std::abs(street.max_speed() - 1.5f) <= 1.5e-6f);
    bool some_frame_slower = false;
    for (const FlowField& frame : street.frames) {
        REQUIRE(all_finite(frame));
        some_frame_slower = some_frame_slower || frame.max_speed() < 1.5f - 1e-4f;
    }
    CHECK(some_frame_slower);
    CHECK(street.frames[0].velocity != street.frames[1].velocity);

    // Frame k is the street at phase k / frames times one factor, the same for every frame and texel.
    const double scale = street.frames[0].at(7, 11).x / street_texel_velocity(7, 11, width, height, 0.0).x;
    for (int k = 0; k < frames; ++k)
        for (int y = 0; y < height; y += 3)
            for (int x = 0; x < width; x += 3) {
                const glm::dvec2 expected = scale * street_texel_velocity(x, y, width, height, double(k) / frames);
                const glm::vec2 got = street.frames[k].at(x, y);
                REQUIRE(std::abs(got.x - expected.x) <= 1e-5);
                REQUIRE(std::abs(got.y - expected.y) <= 1e-5);
            }
    // The frame after the last would be frame 0 again: phase 1 is phase 0.
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::dvec2 wrapped = scale * street_texel_velocity(x, y, width, height, 1.0);
            const glm::vec2 first = street.frames[0].at(x, y);
            REQUIRE(std::abs(wrapped.x - first.x) <= 1e-6);
            REQUIRE(std::abs(wrapped.y - first.y) <= 1e-6);
        }
}

TEST_CASE("make_double_gyre_sequence is one period of make_flow's double gyre under one scale", "[unit][flow]") {
    const int width = 64, height = 32, frames = 8;
    const gsv::FlowSequence gyre = gsv::make_double_gyre_sequence(width, height, frames, 2.0);
    REQUIRE(gyre.frames.size() == static_cast<std::size_t>(frames));
    CHECK(std::abs(gyre.max_speed() - 2.0f) <= 2e-6f);
    // At t = 0 the gyre is at its slowest (df/dx = 1 everywhere): frame 0 is slower than the sequence's top.
    CHECK(gyre.frames[0].max_speed() < 1.9f);
    for (int k = 0; k < frames; ++k) {
        const FlowField alone = gsv::make_flow(FlowKind::DoubleGyre, width, height, 2.0, 10.0 * k / frames);
        // make_flow scales the frame alone to 2; in the sequence it is slower by the common factor's ratio.
        const float ratio = gyre.frames[k].max_speed() / 2.0f;
        INFO("frame " << k);
        for (std::size_t i = 0; i < alone.velocity.size(); ++i)
            REQUIRE(std::abs(gyre.frames[k].velocity[i] - ratio * alone.velocity[i]) <= 4e-6f);
    }
}

TEST_CASE("sequence generators refuse bad arguments with one clear line", "[unit][flow]") {
    CHECK(gsv_error_message([] { gsv::make_vortex_street(16, 8, 0, 1.0); }) ==
          "make_vortex_street: frames must be 1..4096, got 0");
    CHECK(gsv_error_message([] { gsv::make_vortex_street(16, 8, 5000, 1.0); }) ==
          "make_vortex_street: frames must be 1..4096, got 5000");
    CHECK(gsv_error_message([] { gsv::make_double_gyre_sequence(16, 8, -1, 1.0); }) ==
          "make_double_gyre_sequence: frames must be 1..4096, got -1");
    CHECK(gsv_error_message([] { gsv::make_vortex_street(0, 8, 4, 1.0); }) ==
          "make_vortex_street: width must be 1..8192, got 0");
    CHECK(gsv_error_message([] { gsv::make_double_gyre_sequence(8, 8, 4, -2.0); }) ==
          "make_double_gyre_sequence: max_texels_per_step must be finite and >= 0, got -2");
    CHECK(gsv_error_message([] { gsv::make_vortex_street(8192, 8192, 3, 1.0); }) ==
          "make_vortex_street: 3 frames of 8192x8192 texels need 1610612736 bytes of velocities, more than the "
          "1073741824 (1 GiB) a .flow file may hold");
    const gsv::FlowSequence still = gsv::make_vortex_street(8, 4, 2, 0.0);
    for (const FlowField& frame : still.frames) CHECK(all_zero(frame));
}

TEST_CASE("data/flows/vortex_street.flow is the generator's 128x64, 16-frame street", "[unit][flow]") {
    // tests/check_flow_data.sh compares the file with gsv-flow's output byte for byte; this says what it holds.
    const gsv::FlowSequence committed = gsv::load_flow_sequence(committed_flow("vortex_street.flow"));
    CHECK(committed.width == 128);
    CHECK(committed.height == 64);
    REQUIRE(committed.frames.size() == 16);
    CHECK(committed.max_speed() == 1.0f);
    const gsv::FlowSequence generated = gsv::make_vortex_street(128, 64, 16, 1.0);
    for (std::size_t f = 0; f < 16; ++f) REQUIRE(committed.frames[f].velocity == generated.frames[f].velocity);
}
