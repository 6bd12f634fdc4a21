#include "catch.hpp"

#include "common/error.h"
#include "common/flow_field.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
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

TEST_CASE("flow kinds have names and unknown names list the valid ones", "[flow]") {
    for (FlowKind kind : {FlowKind::Rotation, FlowKind::Saddle, FlowKind::Source, FlowKind::DoubleGyre,
                          FlowKind::Vortices})
        CHECK(gsv::flow_kind_from_name(gsv::flow_kind_name(kind)) == kind);
    CHECK(std::string(gsv::flow_kind_name(FlowKind::DoubleGyre)) == "double_gyre");
    CHECK(gsv_error_message([] { gsv::flow_kind_from_name("gyre"); }) ==
          "unknown flow 'gyre' (valid: rotation, saddle, source, double_gyre, vortices)");
}

TEST_CASE("rotation is tangent to circles about the centre and scaled to the requested speed", "[flow]") {
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

TEST_CASE("the centre texel of an odd-sized field is exactly still", "[flow]") {
    for (FlowKind kind : {FlowKind::Rotation, FlowKind::Source, FlowKind::Saddle}) {
        const FlowField field = gsv::make_flow(kind, 65, 33, 1.0);
        CHECK(field.at(32, 16) == glm::vec2(0.0f));
        CHECK(field.at(31, 16) != glm::vec2(0.0f));
    }
}

TEST_CASE("source points straight outward and saddle in along y, out along x", "[flow]") {
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

TEST_CASE("double gyre at t = 0 is two mirrored cells with no flow across x = 1", "[flow]") {
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

TEST_CASE("double gyre velocities are carried from domain units into texels", "[flow]") {
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

TEST_CASE("double gyre is finite and scaled at every time, and moves with time", "[flow]") {
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

TEST_CASE("vortices are deterministic per seed and depend on it", "[flow]") {
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

TEST_CASE("a vortex centred exactly on a texel centre gives no NaN", "[flow]") {
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

TEST_CASE("a vortex's core tends to solid-body rotation without cancellation", "[flow]") {
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

TEST_CASE("vortex cores must be positive", "[flow]") {
    CHECK(gsv_error_message([] { gsv::make_vortex_flow({gsv::Vortex{0, 0, 1, 0.0}}, 8, 8, 1.0); }) ==
          "make_vortex_flow: vortex 0 has core radius 0; it must be positive and finite");
}

TEST_CASE("photo swirl turns a disc and leaves everything beyond its radius still", "[flow]") {
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

TEST_CASE("a field that is zero everywhere stays zero after scaling", "[flow]") {
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

TEST_CASE("make_flow and FlowField::at refuse bad arguments with one clear line", "[flow]") {
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

TEST_CASE(".flow files are little-endian float32 after a one-line header", "[flow]") {
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

TEST_CASE(".flow files round-trip bit for bit", "[flow]") {
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

TEST_CASE("load_flow names the file and the fault in one line", "[flow]") {
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

TEST_CASE("save_flow refuses fields load_flow would refuse", "[flow]") {
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
