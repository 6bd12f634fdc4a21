#include "catch.hpp"

#include "common/core/error.h"
#include "gl_fixture.h"
#include "support/terrain/height_field.h"
#include "reference/terrain/terrain_normal.h"
#include "support/terrain/terrain_procedural.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using gsv::HeightField;
using gsv::ProceduralTerrain;
using gsv::TerrainKind;
using gsv::test::gsv_error_message;
using gsv::test::TempDir;
using gsv::test::source_root;
namespace fs = std::filesystem;

namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string le_float(float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    std::string bytes(4, '\0');
    for (int i = 0; i < 4; ++i) bytes[i] = static_cast<char>(bits >> (8 * i));
    return bytes;
}

std::string le_floats(std::initializer_list<float> values) {
    std::string bytes;
    for (float v : values) bytes += le_float(v);
    return bytes;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

HeightField small_field() {
    HeightField field;
    field.width = 3;
    field.height = 2;
    field.dx_m = 0.1;
    field.dy_m = 30.0 / 7.0;
    field.heights = {-1437.0f, 0.0f, -0.0f, 1e-40f, 3.4e38f, 8848.86f};
    return field;
}

// The largest normal-angle error (radians) between finite differences of `field` with `step` and the exact
// normals of `terrain`, over the samples `pick` accepts.
double worst_angle(const HeightField& field, const ProceduralTerrain& terrain, int step,
                   const std::function<bool(int, int)>& pick) {
    double worst = 0;
    for (int y = 0; y < field.height; ++y)
        for (int x = 0; x < field.width; ++x)
            if (pick(x, y))
                worst = std::max(worst, gsv::normal_angle(gsv::finite_difference_normal(field, x, y, 1.0, step),
                                                          gsv::exact_normal(terrain, gsv::sample_position(field, x, y))));
    return worst;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// The .height file

TEST_CASE("height_field: save and load round-trip every bit, sizes and spacings", "[unit][terrain]") {
    TempDir dir;
    const HeightField field = small_field();
    const fs::path path = dir.path("small.height");
    gsv::save_height_field(path, field);
    const std::string bytes = gsv::test::read_text(path);
    // The shortest texts that read back exactly: 30/7 needs all 16 digits, 0.1 only one.
    CHECK(bytes.substr(0, bytes.find('\n') + 1) == "GSVHEIGHT 1 3 2 0.1 4.285714285714286\n");
    CHECK(bytes.size() == bytes.find('\n') + 1 + 6 * 4);

    const HeightField back = gsv::load_height_field(path);
    CHECK(back.width == 3);
    CHECK(back.height == 2);
    CHECK(back.dx_m == field.dx_m);
    CHECK(back.dy_m == field.dy_m);
    REQUIRE(back.heights.size() == field.heights.size());
    for (std::size_t i = 0; i < field.heights.size(); ++i) CHECK(same_bits(back.heights[i], field.heights[i]));

    gsv::save_height_field(dir.path("again.height"), back);
    CHECK(gsv::test::read_text(dir.path("again.height")) == bytes);
}

TEST_CASE("height_field: at, min, max and sample positions, y counted from the south row", "[unit][terrain]") {
    const HeightField field = small_field();
    CHECK(field.at(0, 0) == -1437.0f);
    CHECK(field.at(2, 1) == 8848.86f);
    CHECK(field.at(0, 1) == 1e-40f);
    CHECK(field.min_height() == -1437.0f);
    CHECK(field.max_height() == 3.4e38f);
    CHECK(HeightField{}.min_height() == 0.0f);
    const glm::dvec2 p = gsv::sample_position(field, 2, 1);
    CHECK(p.x == Approx(0.25));
    CHECK(p.y == Approx(1.5 * 30.0 / 7.0));
    CHECK(contains(gsv_error_message([&] { (void)field.at(3, 0); }), "sample (3, 0) is outside the 3x2 grid"));
    CHECK(contains(gsv_error_message([&] { (void)gsv::sample_position(field, 0, -1); }), "outside"));
}

TEST_CASE("height_field: the loader refuses a bad file with one line naming the file and the fault", "[unit][terrain]") {
    TempDir dir;
    const std::string heights_2x2 = le_floats({1, 2, 3, 4});
    struct Case {
        const char* name;
        std::string content;
        const char* expected;
    };
    const std::vector<Case> cases = {
        {"empty", "", "file is empty"},
        {"flow", "GSVFLOW 1 2 2\n" + heights_2x2 + heights_2x2, "not a .height file"},
        {"png", std::string("\x89PNG\r\n\x1a\n", 8), "not a .height file"},
        {"long_header", "GSVHEIGHT 1 2 2 1" + std::string(200, '0'), "no newline within its first 128 bytes"},
        {"version", "GSVHEIGHT 2 2 2 1 1\n" + heights_2x2, "unsupported version '2'"},
        {"few_fields", "GSVHEIGHT 1 2 2 1\n" + heights_2x2, "is not 'GSVHEIGHT 1 <width> <height> <dx_m> <dy_m>'"},
        {"units_field", "GSVHEIGHT 1 2 2 1 1 m\n" + heights_2x2, "is not 'GSVHEIGHT 1"},
        {"width_zero", "GSVHEIGHT 1 0 2 1 1\n", "width '0' is not in 1..8192"},
        {"width_big", "GSVHEIGHT 1 8193 2 1 1\n", "width '8193' is not in 1..8192"},
        {"height_sign", "GSVHEIGHT 1 2 -2 1 1\n", "height '-2' is not in 1..8192"},
        {"height_text", "GSVHEIGHT 1 2 two 1 1\n", "height 'two' is not in 1..8192"},
        {"dx_zero", "GSVHEIGHT 1 2 2 0 1\n" + heights_2x2, "dx_m '0' is not a positive, finite number of metres"},
        {"dx_negative", "GSVHEIGHT 1 2 2 -30 1\n" + heights_2x2, "dx_m '-30' is not a positive, finite"},
        {"dy_nan", "GSVHEIGHT 1 2 2 1 nan\n" + heights_2x2, "dy_m 'nan' is not a positive, finite"},
        {"dy_inf", "GSVHEIGHT 1 2 2 1 inf\n" + heights_2x2, "dy_m 'inf' is not a positive, finite"},
        {"dy_overflow", "GSVHEIGHT 1 2 2 1 1e999\n" + heights_2x2, "dy_m '1e999' is not a positive, finite"},
        {"dx_comma", "GSVHEIGHT 1 2 2 74,5 1\n" + heights_2x2, "dx_m '74,5' is not a positive, finite"},
        {"dx_empty", "GSVHEIGHT 1 2 2  1\n" + heights_2x2, "dx_m '' is not a positive, finite"},
        {"truncated", "GSVHEIGHT 1 2 2 1 1\n" + heights_2x2.substr(0, 13),
         "expected 16 bytes of heights, found 13 (2x2 samples, 4 bytes each)"},
        {"no_heights", "GSVHEIGHT 1 2 2 1 1\n", "expected 16 bytes of heights, found 0"},
        // A header that promises 256 MiB over 4 bytes: refused after reading what is there, not after
        // allocating what was promised.
        {"lying_header", "GSVHEIGHT 1 8192 8192 1 1\n" + le_float(1), "expected 268435456 bytes of heights, found 4"},
        {"trailing", "GSVHEIGHT 1 2 2 1 1\n" + heights_2x2 + "abc", "3 trailing bytes after the 16 bytes of heights"},
        {"nan", "GSVHEIGHT 1 2 2 1 1\n" + le_floats({1, std::numeric_limits<float>::quiet_NaN(), 3, 4}),
         "height at sample (1, 0) is NaN"},
        {"inf", "GSVHEIGHT 1 2 2 1 1\n" + le_floats({1, 2, -std::numeric_limits<float>::infinity(), 4}),
         "height at sample (0, 1) is infinite"},
    };
    for (const Case& c : cases) {
        const fs::path path = dir.write(std::string(c.name) + ".height", c.content);
        const std::string message = gsv_error_message([&] { (void)gsv::load_height_field(path); });
        INFO(c.name << ": " << message);
        CHECK(contains(message, c.expected));
        CHECK(contains(message, path.string()));
        CHECK(!contains(message, "\n"));
    }

    const fs::path missing = dir.path("missing.height");
    const std::string message = gsv_error_message([&] { (void)gsv::load_height_field(missing); });
    CHECK(message == "cannot read height file '" + missing.string() + "': no such file");
    CHECK(contains(gsv_error_message([&] { (void)gsv::load_height_field(dir.path()); }), "is a directory"));
}

TEST_CASE("height_field: save refuses what the loader would refuse, before creating the file", "[unit][terrain]") {
    TempDir dir;
    const fs::path path = dir.path("refused.height");
    const auto refusal = [&](const HeightField& field) {
        return gsv_error_message([&] { gsv::save_height_field(path, field); });
    };
    HeightField field = small_field();
    field.width = 0;
    CHECK(contains(refusal(field), "size 0x2 is not in 1..8192 each way"));
    field = small_field();
    field.dx_m = 0;
    CHECK(contains(refusal(field), "dx_m 0 is not a positive, finite number of metres"));
    field.dx_m = std::numeric_limits<double>::infinity();
    CHECK(contains(refusal(field), "dx_m inf is not a positive"));
    field = small_field();
    field.dy_m = std::nan("");
    CHECK(contains(refusal(field), "dy_m nan is not a positive"));
    field = small_field();
    field.heights.pop_back();
    CHECK(contains(refusal(field), "5 heights for 3x2 samples, which need 6"));
    field = small_field();
    field.heights[4] = std::numeric_limits<float>::infinity();
    CHECK(contains(refusal(field), "height at sample (1, 1) is infinite"));
    CHECK(!fs::exists(path));
}

// ---------------------------------------------------------------------------------------------------------
// The real elevation models in data/terrain (scripts/convert-dem.py; sources in data/README.md)

TEST_CASE("height_field: data/terrain/jacksboro_fault.height loads, south row first, in metres", "[unit][terrain]") {
    const fs::path path = source_root() / "data/terrain/jacksboro_fault.height";
    const HeightField field = gsv::load_height_field(path);
    WARN("jacksboro_fault: " << field.width << "x" << field.height << " samples, " << field.dx_m << " x "
                             << field.dy_m << " m apart, heights " << field.min_height() << " .. "
                             << field.max_height() << " m");
    CHECK(field.width == 403);
    CHECK(field.height == 344);
    // 3 arc-seconds at 36.59 N on the WGS84 ellipsoid (data/README.md).
    CHECK(field.dx_m == 74.573);
    CHECK(field.dy_m == 92.475);
    // Integer metres of the Cumberland Plateau: whole numbers, a few hundred to about a thousand metres.
    CHECK(field.min_height() == 236.0f);
    CHECK(field.max_height() == 1076.0f);
    for (float h : field.heights) REQUIRE(h == std::round(h));
    // The .npz lists rows north first; its last row must be this file's row 0 and its first row the top one.
    CHECK(field.at(0, 0) == 545.0f);
    CHECK(field.at(1, 0) == 543.0f);
    CHECK(field.at(0, 343) == 483.0f);
    CHECK(field.at(1, 343) == 487.0f);

    // The kit's writer gives the converter's bytes: the two agree on the format, the header text included.
    TempDir dir;
    gsv::save_height_field(dir.path("again.height"), field);
    CHECK(gsv::test::read_text(dir.path("again.height")) == gsv::test::read_text(path));
}

TEST_CASE("height_field: data/terrain/topobathy.height loads, sea to the south-west, summits to the north-east",
          "[unit][terrain]") {
    const fs::path path = source_root() / "data/terrain/topobathy.height";
    const HeightField field = gsv::load_height_field(path);
    WARN("topobathy: " << field.width << "x" << field.height << " samples, " << field.dx_m << " x " << field.dy_m
                       << " m apart, heights " << field.min_height() << " .. " << field.max_height() << " m");
    CHECK(field.width == 120);
    CHECK(field.height == 91);
    // 2 arc-minutes of longitude at 49.0 N; the Mercator rows are as far apart as the columns to 0.3%.
    CHECK(field.dx_m == 2439.07);
    CHECK(field.dy_m == 2431.554);
    CHECK(field.min_height() == -1437.0f);
    CHECK(field.max_height() == 2205.0f);
    const auto where = [&](float value) {
        const auto it = std::find(field.heights.begin(), field.heights.end(), value);
        const long index = static_cast<long>(it - field.heights.begin());
        return glm::ivec2(index % field.width, index / field.width);
    };
    // The continental slope off the Pacific coast is the deepest (south-west corner); the Coast
    // Mountains north of Vancouver, by Mount Garibaldi, the highest (north-east).
    const glm::ivec2 deepest = where(field.min_height()), highest = where(field.max_height());
    CHECK(deepest.x < field.width / 4);
    CHECK(deepest.y < field.height / 4);
    CHECK(highest.x > field.width * 2 / 3);
    CHECK(highest.y > field.height * 3 / 4);
    int sea = 0;
    for (float h : field.heights) sea += h < 0;
    WARN("topobathy: " << sea << " of " << field.heights.size() << " samples below sea level");
    CHECK(sea > int(field.heights.size()) / 5);
    CHECK(sea < int(field.heights.size()) * 3 / 5);

    TempDir dir;
    gsv::save_height_field(dir.path("again.height"), field);
    CHECK(gsv::test::read_text(dir.path("again.height")) == gsv::test::read_text(path));
}

// ---------------------------------------------------------------------------------------------------------
// Procedural terrains and their exact gradients

TEST_CASE("terrain: Franke and sin-cos gradients match central differences to 1e-8", "[unit][terrain]") {
    struct Function {
        const char* name;
        double (*value)(double, double);
        glm::dvec2 (*gradient)(double, double);
    };
    const Function functions[] = {{"franke", gsv::franke, gsv::franke_gradient},
                                  {"sin_cos", gsv::sin_cos, gsv::sin_cos_gradient}};
    const double h = 1e-6;
    for (const Function& f : functions) {
        double worst = 0;
        for (int i = 0; i <= 20; ++i)
            for (int j = 0; j <= 20; ++j) {
                // Off the lattice of the functions' own symmetries, the square's edges included.
                const double u = i / 20.0 + 0.0123 * (i < 20), v = j / 20.0 + 0.0071 * (j < 20);
                const glm::dvec2 exact = f.gradient(u, v);
                const glm::dvec2 central((f.value(u + h, v) - f.value(u - h, v)) / (2 * h),
                                         (f.value(u, v + h) - f.value(u, v - h)) / (2 * h));
                worst = std::max({worst, std::abs(exact.x - central.x), std::abs(exact.y - central.y)});
            }
        WARN(f.name << ": largest |analytic - central difference| of the gradient " << worst);
        CHECK(worst < 1e-8);
    }
    // Franke's formula evaluated by hand (in Python) at two points, its highest hill near (0.2, 0.2) included.
    CHECK(gsv::franke(0.2, 0.2) == Approx(1.2185807041679817).epsilon(1e-14));
    CHECK(gsv::franke(0.5, 0.5) == Approx(0.3257620892806842).epsilon(1e-14));
    CHECK(gsv::sin_cos(0.125, 0.0) == Approx(1.0));
}

TEST_CASE("terrain: slopes in metres per metre follow the chain rule of extent and amplitude", "[unit][terrain]") {
    for (TerrainKind kind : {TerrainKind::Franke, TerrainKind::SinCos}) {
        const ProceduralTerrain terrain{kind, 2500.0, 400.0};
        const double h = 1e-6 * terrain.extent_m;
        for (const glm::dvec2& p : {glm::dvec2(300, 700), glm::dvec2(1234.5, 2100), glm::dvec2(2400, 10)}) {
            const glm::dvec2 slope = gsv::terrain_slope(terrain, p);
            const double sx = (gsv::terrain_height(terrain, p + glm::dvec2(h, 0)) -
                               gsv::terrain_height(terrain, p - glm::dvec2(h, 0))) / (2 * h);
            const double sz = (gsv::terrain_height(terrain, p + glm::dvec2(0, h)) -
                               gsv::terrain_height(terrain, p - glm::dvec2(0, h))) / (2 * h);
            CHECK(slope.x == Approx(sx).margin(1e-8));
            CHECK(slope.y == Approx(sz).margin(1e-8));
        }
    }
    CHECK(gsv::terrain_kind_from_name("sin_cos") == TerrainKind::SinCos);
    CHECK(std::string(gsv::terrain_kind_name(TerrainKind::Franke)) == "franke");
    CHECK(gsv_error_message([] { (void)gsv::terrain_kind_from_name("alps"); }) ==
          "unknown terrain 'alps' (known: franke, sin_cos, flat)");
    CHECK(contains(gsv_error_message([] { (void)gsv::terrain_height({TerrainKind::Franke, 0.0, 1.0}, {0, 0}); }),
                   "extent 0.000000 m must be positive and finite"));
}

TEST_CASE("terrain: make_procedural samples cell centres over the square", "[unit][terrain]") {
    const ProceduralTerrain terrain{TerrainKind::Franke, 1000.0, 250.0};
    const HeightField field = gsv::make_procedural(terrain, 40, 25);
    CHECK(field.dx_m == 25.0);
    CHECK(field.dy_m == 40.0);
    CHECK(field.at(0, 0) == float(250.0 * gsv::franke(0.5 / 40, 0.5 / 25)));
    CHECK(field.at(39, 24) == float(250.0 * gsv::franke(39.5 / 40, 24.5 / 25)));
    CHECK(field.at(7, 3) == float(gsv::terrain_height(terrain, {7.5 * 25, 3.5 * 40})));
    CHECK(contains(gsv_error_message([&] { (void)gsv::make_procedural(terrain, 0, 5); }),
                   "make_procedural: size 0x5 is not in 1..8192 each way"));
}

// ---------------------------------------------------------------------------------------------------------
// Finite-difference normals, the CPU reference of lab 04's shader

TEST_CASE("terrain normals: flat ground gives exactly up, at every sample, step and exaggeration", "[unit][terrain]") {
    HeightField level = gsv::make_procedural({TerrainKind::Flat, 100.0, 50.0}, 7, 5);
    for (float h : level.heights) REQUIRE(h == 0.0f);
    HeightField plateau = level;
    std::fill(plateau.heights.begin(), plateau.heights.end(), 1234.5f);
    for (const HeightField* field : {&level, &plateau})
        for (int y = 0; y < field->height; ++y)
            for (int x = 0; x < field->width; ++x)
                for (int step : {1, 2, 3, 9})
                    for (double e : {0.0, 1.0, 1e6, 1e300}) {
                        const glm::dvec3 n = gsv::finite_difference_normal(*field, x, y, e, step);
                        REQUIRE(n.x == 0.0);
                        REQUIRE(n.y == 1.0);
                        REQUIRE(n.z == 0.0);
                        REQUIRE(!std::signbit(n.x));
                        REQUIRE(!std::signbit(n.z));
                    }
    CHECK(gsv::exact_normal({TerrainKind::Flat, 100.0, 50.0}, {3, 4}) == glm::dvec3(0, 1, 0));
}

TEST_CASE("terrain normals: the slope form is the normalised cross product of the tangents, oriented up",
          "[unit][terrain]") {
    const HeightField field = gsv::make_procedural({TerrainKind::SinCos, 900.0, 120.0}, 30, 20);
    for (int step : {1, 2})
        for (const glm::ivec2& s : {glm::ivec2(5, 7), glm::ivec2(17, 11), glm::ivec2(2, 2)})
            for (double e : {0.5, 3.0}) {
                const double dh_x = e * (field.at(s.x + step, s.y) - double(field.at(s.x - step, s.y)));
                const double dh_z = e * (field.at(s.x, s.y + step) - double(field.at(s.x, s.y - step)));
                const glm::dvec3 along_x(2 * step * field.dx_m, dh_x, 0), along_z(0, dh_z, 2 * step * field.dy_m);
                const glm::dvec3 expected = glm::normalize(glm::cross(along_z, along_x));
                const glm::dvec3 n = gsv::finite_difference_normal(field, s.x, s.y, e, step);
                CHECK(expected.y > 0);
                CHECK(glm::length(n - expected) < 1e-14);
            }
}

TEST_CASE("terrain normals: central differences inside converge at second order to the exact normals",
          "[unit][terrain]") {
    // A non-square grid over a square: dx_m != dy_m, so a swapped spacing would show.
    for (TerrainKind kind : {TerrainKind::Franke, TerrainKind::SinCos}) {
        const ProceduralTerrain terrain{kind, 1000.0, 200.0};
        const HeightField field = gsv::make_procedural(terrain, 512, 384);
        const auto inside = [&](int x, int y) {
            return x >= 16 && y >= 16 && x < field.width - 16 && y < field.height - 16;
        };
        const double e8 = worst_angle(field, terrain, 8, inside), e4 = worst_angle(field, terrain, 4, inside),
                     e2 = worst_angle(field, terrain, 2, inside);
        WARN(gsv::terrain_kind_name(kind) << " inside, worst normal-angle error in degrees: step 8 " << e8 * kRadToDeg
                                          << ", step 4 " << e4 * kRadToDeg << ", step 2 " << e2 * kRadToDeg
                                          << "; ratios " << e8 / e4 << ", " << e4 / e2);
        CHECK(e8 / e4 == Approx(4.0).margin(0.3));
        CHECK(e4 / e2 == Approx(4.0).margin(0.3));
    }
}

TEST_CASE("terrain normals: one-sided differences at the border converge at first order, clamped ones not",
          "[unit][terrain]") {
    for (TerrainKind kind : {TerrainKind::Franke, TerrainKind::SinCos}) {
        const ProceduralTerrain terrain{kind, 1000.0, 200.0};
        const HeightField field = gsv::make_procedural(terrain, 512, 384);
        // The south border row, away from the corners: one-sided along z, central along x. (Not the west
        // column: there sin-cos has no curvature along x, sin(0) = 0, so the first-order term vanishes.)
        const auto south = [&](int x, int y) { return y == 0 && x >= 16 && x < field.width - 16; };
        const double e8 = worst_angle(field, terrain, 8, south), e4 = worst_angle(field, terrain, 4, south),
                     e2 = worst_angle(field, terrain, 2, south);
        // What a shader gets from a central difference of clamp-to-edge samples, which halves the slope at
        // the border: its error does not shrink with the step.
        const auto clamped_error = [&](int step) {
            double worst = 0;
            for (int x = 16; x < field.width - 16; ++x) {
                const glm::dvec2 slope((double(field.at(x + step, 0)) - field.at(x - step, 0)) / (2 * step * field.dx_m),
                                       (double(field.at(x, step)) - field.at(x, 0)) / (2 * step * field.dy_m));
                worst = std::max(worst, gsv::normal_angle(gsv::normal_from_slopes(slope, 1.0),
                                                          gsv::exact_normal(terrain, gsv::sample_position(field, x, 0))));
            }
            return worst;
        };
        const double c8 = clamped_error(8), c2 = clamped_error(2);
        WARN(gsv::terrain_kind_name(kind) << " south border, worst normal-angle error in degrees: one-sided step 8 "
                                          << e8 * kRadToDeg << ", 4 " << e4 * kRadToDeg << ", 2 " << e2 * kRadToDeg
                                          << " (ratios " << e8 / e4 << ", " << e4 / e2 << "); clamped central step 8 "
                                          << c8 * kRadToDeg << ", step 2 " << c2 * kRadToDeg);
        CHECK(e8 / e4 == Approx(2.0).margin(0.3));
        CHECK(e4 / e2 == Approx(2.0).margin(0.3));
        // Only Franke's border is generic. Sin-cos's south border is a mirror line of the terrain (cos is even),
        // where the true slope across it is 0 and a halved slope happens to be closer to right than a
        // one-sided one.
        if (kind == TerrainKind::Franke) {
            CHECK(c2 > 0.8 * c8);
            CHECK(e2 < c2 / 10);
        }
    }
}

TEST_CASE("terrain normals: a huge exaggeration gives a finite unit normal that still points up", "[unit][terrain]") {
    const HeightField field = gsv::make_procedural({TerrainKind::Franke, 1000.0, 200.0}, 64, 48);
    for (double e : {1e6, 1e300})
        for (int y = 0; y < field.height; y += 7)
            for (int x = 0; x < field.width; x += 5) {
                const glm::dvec3 n = gsv::finite_difference_normal(field, x, y, e, 1);
                REQUIRE(std::isfinite(n.x));
                REQUIRE(std::isfinite(n.y));
                REQUIRE(std::isfinite(n.z));
                REQUIRE(glm::length(n) == Approx(1.0).margin(1e-12));
                REQUIRE(n.y > 0);
                REQUIRE(n.y < 1e-3);
            }
    const glm::dvec3 exact = gsv::exact_normal({TerrainKind::Franke, 1000.0, 200.0}, {300, 300}, 1e6);
    CHECK(glm::length(exact) == Approx(1.0).margin(1e-12));
}

TEST_CASE("terrain normals: 8-bit heights make terraces whose normals are far off the float ones", "[unit][terrain]") {
    const ProceduralTerrain terrain{TerrainKind::Franke, 1000.0, 200.0};
    const HeightField field = gsv::make_procedural(terrain, 256, 256);
    // What an 8-bit height texture (GL_R8) holds: 256 levels from the lowest height to the highest.
    HeightField quantised = field;
    const double low = field.min_height(), range = field.max_height() - low;
    for (float& h : quantised.heights) h = float(low + std::round((h - low) / range * 255.0) / 255.0 * range);

    const auto errors = [&](const HeightField& f) {
        double sum = 0, worst = 0;
        int count = 0, flat_steps = 0;
        for (int y = 1; y < f.height - 1; ++y)
            for (int x = 1; x < f.width - 1; ++x) {
                const double a = gsv::normal_angle(gsv::finite_difference_normal(f, x, y, 1.0, 1),
                                                   gsv::exact_normal(terrain, gsv::sample_position(f, x, y)));
                sum += a;
                worst = std::max(worst, a);
                flat_steps += f.at(x + 1, y) == f.at(x - 1, y);
                ++count;
            }
        return std::vector<double>{sum / count * kRadToDeg, worst * kRadToDeg, double(flat_steps) / count};
    };
    const std::vector<double> exact_float = errors(field), eight_bit = errors(quantised);
    WARN("franke 256x256, step 1, normal-angle error in degrees: float heights mean " << exact_float[0] << ", worst "
         << exact_float[1] << "; 8-bit heights mean " << eight_bit[0] << ", worst " << eight_bit[1]
         << "; samples on a terrace along x (no height change over 2 samples): float " << exact_float[2]
         << ", 8-bit " << eight_bit[2]);
    CHECK(eight_bit[0] > 10 * exact_float[0]);
    CHECK(eight_bit[2] > 0.1);
    CHECK(exact_float[2] < 0.01);
}

TEST_CASE("terrain normals: bad arguments are refused with one line", "[unit][terrain]") {
    const HeightField field = gsv::make_procedural({TerrainKind::SinCos, 100.0, 10.0}, 8, 4);
    CHECK(gsv_error_message([&] { (void)gsv::finite_difference_normal(field, 8, 0, 1.0, 1); }) ==
          "finite_difference_normal: sample (8, 0) is outside the 8x4 grid");
    CHECK(gsv_error_message([&] { (void)gsv::finite_difference_normal(field, 0, 0, 1.0, 0); }) ==
          "finite_difference_normal: step 0 must be at least 1");
    CHECK(contains(gsv_error_message([&] { (void)gsv::finite_difference_normal(field, 0, 0, -1.0, 1); }),
                   "exaggeration -1.000000 must be finite and >= 0"));
    HeightField broken = field;
    broken.heights.pop_back();
    CHECK(contains(gsv_error_message([&] { (void)gsv::finite_difference_normal(broken, 0, 0, 1.0, 1); }),
                   "31 heights for a 8x4 field"));
    broken = field;
    broken.dy_m = 0;
    CHECK(contains(gsv_error_message([&] { (void)gsv::finite_difference_normal(broken, 0, 0, 1.0, 1); }),
                   "must be positive and finite"));
    // One sample across: no neighbour along that axis, so no slope along it.
    HeightField column = gsv::make_procedural({TerrainKind::Franke, 100.0, 10.0}, 1, 6);
    const glm::dvec3 n = gsv::finite_difference_normal(column, 0, 2, 1.0, 3);
    CHECK(n.x == 0.0);
    CHECK(n.z != 0.0);
}
