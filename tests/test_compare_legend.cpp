// `labXX compare` and `render --legend` end to end, run as a student or a lecturer runs them.
#include "catch.hpp"
#include "common/image/comparison_image.h"
#include "common/image/image.h"
#include "common/app/known_mistake_pictures.h"
#include "common/io/json.h"
#include "grader/src/diagnose/mutant_kit.h"
#include "grader/src/run/process.h"
#include "lab_runner.h"
#include "test_support.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using gsv::Image;

namespace {

gsv::ProcessResult run(const fs::path& binary, const std::vector<std::string>& args, const fs::path& dir) {
    std::vector<std::string> argv{binary.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    gsv::ProcessLimits limits;
    limits.timeout = std::chrono::milliseconds(120000);
    return gsv::run_process(argv, dir, limits);
}

// A lab binary copied alone (or with others) into a folder of its own: a student's build without the solutions.
fs::path copy_binary(const std::string& from, const fs::path& folder, const std::string& as) {
    fs::create_directories(folder);
    fs::copy_file(gsv::test::bin_dir() / from, folder / as, fs::copy_options::overwrite_existing);
    fs::permissions(folder / as, fs::perms::owner_all, fs::perm_options::add);
    return folder / as;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool same_pixels(const Image& a, const Image& b) { return a.width == b.width && a.height == b.height && a.rgba == b.rgba; }

Image crop(const Image& image, const std::array<int, 4>& r) {
    Image out(r[2] - r[0], r[3] - r[1]);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) std::copy(image.at(r[0] + x, r[1] + y), image.at(r[0] + x, r[1] + y) + 4, out.at(x, y));
    return out;
}

bool is_magenta(const std::uint8_t* p) { return p[0] > 100 && p[0] == p[2] && p[1] == 0; }

}  // namespace

TEST_CASE("compare: lab01's starter against its solution, rendered now, differs where the TODO paints its not-done colour", "[lab][labs]") {
    gsv::test::TempDir dir;
    const auto result = run(gsv::test::bin_dir() / "lab01", {"compare", "--case", "phong", "--size", "128x128", "--out",
                                                              dir.path("compare.png").string()}, dir.path());
    INFO(result.output);
    REQUIRE(result.exit_code == 0);
    CHECK(contains(result.output, "against lab01_solution, rendered now: RMSE"));
    CHECK(contains(result.output, "difference x"));

    // The same two images rendered on their own, composed the same way: the file is exactly that.
    const auto yours = gsv::test::render("lab01", {}, dir.path(), "yours", {"--case", "phong"});
    const auto reference = gsv::test::render("lab01_solution", {}, dir.path(), "reference", {"--case", "phong"});
    REQUIRE(yours.exit_code() == 0);
    REQUIRE(reference.exit_code() == 0);
    const Image mine = gsv::read_png(yours.png), theirs = gsv::read_png(reference.png);
    gsv::ComparisonLayout layout;
    const Image expected = gsv::compose_comparison(mine, theirs, "yours: lab01 (starter)", "reference: lab01_solution, rendered now", &layout);
    const Image written = gsv::read_png(dir.path("compare.png"));
    REQUIRE(same_pixels(written, expected));

    const Image difference = crop(written, layout.panels[2]);
    long magenta = 0, agree = 0;
    for (int y = 0; y < mine.height; ++y)
        for (int x = 0; x < mine.width; ++x) {
            const std::uint8_t* d = difference.at(x, y);
            const bool differs = d[0] + d[1] + d[2] > 0;
            if (is_magenta(mine.at(x, y)) && !is_magenta(theirs.at(x, y))) {
                ++magenta;
                CHECK(differs);
            }
            if (std::equal(mine.at(x, y), mine.at(x, y) + 3, theirs.at(x, y))) {
                ++agree;
                CHECK_FALSE(differs);
            }
        }
    CHECK(magenta > mine.width * mine.height / 10);
    CHECK(agree > 0);  // the background
    CHECK(same_pixels(crop(written, layout.panels[0]), mine));
    CHECK(same_pixels(crop(written, layout.panels[1]), theirs));
}

TEST_CASE("compare: the solution against itself, a copy named as the student's beside it, differs nowhere", "[lab][labs]") {
    gsv::test::TempDir dir;
    const fs::path lab = copy_binary("lab01_solution", dir.path("bin"), "lab01");
    copy_binary("lab01_solution", dir.path("bin"), "lab01_solution");
    const auto result = run(lab, {"compare", "--case", "gooch", "--size", "96x96", "--out", dir.path("self.png").string()}, dir.path());
    INFO(result.output);
    REQUIRE(result.exit_code == 0);
    CHECK(contains(result.output, "RMSE 0, max difference 0 of 255 (RGB), 0 of 9216 pixels differ"));
    const Image written = gsv::read_png(dir.path("self.png"));
    gsv::ComparisonLayout layout;
    const Image same(96, 96);
    const Image expected_shape = gsv::compose_comparison(same, same, "yours: lab01 (solution)", "reference: lab01_solution, rendered now", &layout);
    REQUIRE(written.width == expected_shape.width);
    REQUIRE(written.height == expected_shape.height);
    const Image yours = crop(written, layout.panels[0]);
    CHECK(same_pixels(yours, crop(written, layout.panels[1])));
    CHECK_FALSE(gsv::is_blank(yours));
    const Image difference = crop(written, layout.panels[2]);
    CHECK(gsv::is_blank(difference));
    CHECK(difference.at(0, 0)[0] == 0);
}

TEST_CASE("compare: with no solution beside it (a student's kit) the case's golden image is the reference, at its size", "[lab][labs]") {
    gsv::test::TempDir dir;
    const fs::path lab = copy_binary("lab01", dir.path("bin"), "lab01");
    const auto result = run(lab, {"compare", "--case", "phong", "--out", dir.path("golden.png").string()}, dir.path());
    INFO(result.output);
    REQUIRE(result.exit_code == 0);
    CHECK(contains(result.output, "against golden image grader/golden/lab01/phong.png: RMSE"));
    const Image golden = gsv::read_png(fs::path(GSV_SOURCE_ROOT) / "grader" / "golden" / "lab01" / "phong.png");
    const std::string size = std::to_string(golden.width) + "x" + std::to_string(golden.height);
    const auto yours = run(lab, {"render", "--case", "phong", "--size", size, "--out", dir.path("yours.png").string()}, dir.path());
    REQUIRE(yours.exit_code == 0);
    // The starter's phong is a TODO not started as the kit ships its picture: the fourth view says so.
    const Image mine = gsv::read_png(dir.path("yours.png"));
    const auto panel = gsv::known_mistake_panel(gsv::read_known_mistake_pictures(GSV_SOURCE_ROOT, "lab01"), "phong", mine, golden);
    REQUIRE(panel);
    CHECK(contains(panel->label, "not started"));
    const Image expected = gsv::compose_comparison(mine, golden, "yours: lab01 (starter)",
                                                   "reference: golden image grader/golden/lab01/phong.png", nullptr, &*panel);
    CHECK(same_pixels(gsv::read_png(dir.path("golden.png")), expected));
}

TEST_CASE("compare: where yours is a known mistake's picture (the pictures the kit ships), it is the fourth view, with what went wrong", "[lab][labs]") {
    // lab01's solution with the normal left in the model's space, in a kit of its own with no solution beside the lab:
    // compared with the golden image of "stretched", the case that mistake fails.
    gsv::test::TempDir dir;
    const gsv::Json spec = gsv::read_json_file(fs::path(GSV_SOURCE_ROOT) / "tests" / "mutants" / "lab01.json");
    const gsv::Json* mistake = nullptr;
    for (const gsv::Json& m : spec.array_at("mutants").as_array())
        if (m.string_at("name") == "the normal left in the model's space") mistake = &m;
    REQUIRE(mistake);
    gsv::make_edited_kit(dir.path("edited"), GSV_SOURCE_ROOT, gsv::test::bin_dir(), "lab01", "lab01_gooch", *mistake);
    fs::create_directory_symlink(fs::path(GSV_SOURCE_ROOT) / "grader", dir.path("edited/kit/grader"));
    const fs::path lab = dir.path("edited/bin/lab01");
    const auto compare = [&](const std::string& case_name, const fs::path& out) {
        std::vector<std::string> argv{lab.string(), "compare", "--case", case_name, "--out", out.string()};
        gsv::ProcessLimits limits;
        limits.timeout = std::chrono::milliseconds(120000);
        return gsv::run_process(argv, dir.path(), limits, {"GSV_ROOT=" + dir.path("edited/kit").string()});
    };
    const auto result = compare("stretched", dir.path("stretched.png"));
    INFO(result.output);
    REQUIRE(result.exit_code == 0);
    CHECK(contains(result.output, "| a known mistake's picture"));
    CHECK(contains(result.output, "what went wrong: looks like a known mistake in L01-T1: " + mistake->string_at("says") +
                                      " (its picture, reduced)"));
    const Image golden = gsv::read_png(fs::path(GSV_SOURCE_ROOT) / "grader" / "golden" / "lab01" / "stretched.png");
    const Image written = gsv::read_png(dir.path("stretched.png"));
    gsv::ComparisonLayout three;
    gsv::compose_comparison(golden, golden, "a", "b", &three);
    CHECK(written.width > three.panels[2][2] + golden.width);  // a fourth panel past the difference
    // A case the mistake draws right: three views, no mistake named.
    const auto right = compare("diffuse", dir.path("diffuse.png"));
    INFO(right.output);
    REQUIRE(right.exit_code == 0);
    CHECK_FALSE(contains(right.output, "what went wrong"));
}

TEST_CASE("compare: no reference, a demo without a golden image, changed settings, another size, an unknown case: one line each", "[lab][labs]") {
    gsv::test::TempDir dir;
    const fs::path alone = copy_binary("lab01", dir.path("bin"), "lab01");
    struct Bad {
        fs::path binary;
        std::vector<std::string> args;
        int status;
        std::string says;
    };
    const std::vector<Bad> bad = {
        {alone, {"compare"}, 1, "no reference to compare with: there is no lab01_solution beside"},
        {alone, {"compare", "--case", "coarse"}, 1, "no golden image"},
        {alone, {"compare", "--case", "phong", "--set", "shininess=16"}, 1, "not with shininess changed"},
        {alone, {"compare", "--case", "phong", "--size", "64x64"}, 1, "differs from the golden image's 256x256"},
        {alone, {"compare", "--case", "nosuch"}, 2, "unknown case 'nosuch'"},
        {gsv::test::bin_dir() / "lab01", {"compare", "--case", "phong", "--legend"}, 2, "--legend is for render and animate"},
    };
    for (const Bad& b : bad) {
        const auto result = run(b.binary, b.args, dir.path());
        INFO(b.args.back() << ": " << result.output);
        CHECK(result.exit_code == b.status);
        CHECK(contains(result.output, b.says));
        CHECK(gsv::test::lines_of(result.output).size() == 1);
    }
    CHECK_FALSE(fs::exists(dir.path("lab01-compare.png")));
}

TEST_CASE("render --legend: lab 07's picture unchanged, and every colour it draws is in the legend beside it", "[lab][labs]") {
    gsv::test::TempDir dir;
    const std::vector<std::string> settings{"element_edges=off", "auto_range=off", "range_min=-0.3", "range_max=0.3"};
    // Tall, so the bar has a row for every few levels of its colours.
    const auto plain = gsv::test::render("lab07_solution", settings, dir.path(), "plain", {"--size", "96x640"});
    const auto legend = gsv::test::render("lab07_solution", settings, dir.path(), "legend", {"--size", "96x640", "--legend"});
    INFO(legend.process.output);
    REQUIRE(plain.exit_code() == 0);
    REQUIRE(legend.exit_code() == 0);
    const Image picture = gsv::read_png(plain.png), shown = gsv::read_png(legend.png);
    REQUIRE(shown.width > picture.width + 40);
    REQUIRE(shown.height >= picture.height);
    CHECK(same_pixels(crop(shown, {0, 0, picture.width, picture.height}), picture));

    std::set<std::array<int, 3>> panel;
    for (int y = 0; y < shown.height; ++y)
        for (int x = picture.width; x < shown.width; ++x) panel.insert({shown.at(x, y)[0], shown.at(x, y)[1], shown.at(x, y)[2]});
    const std::uint8_t* background = picture.at(0, 0);
    long checked = 0, missing = 0;
    std::set<std::array<int, 3>> drawn;
    for (int y = 0; y < picture.height; y += 3)
        for (int x = 0; x < picture.width; x += 3) {
            const std::uint8_t* p = picture.at(x, y);
            if (std::equal(p, p + 3, background)) continue;
            drawn.insert({p[0], p[1], p[2]});
            ++checked;
            // Within 2 levels: the bar interpolates 256 samples of the same colour map.
            const bool found = std::any_of(panel.begin(), panel.end(), [&](const std::array<int, 3>& c) {
                return std::abs(c[0] - p[0]) <= 2 && std::abs(c[1] - p[1]) <= 2 && std::abs(c[2] - p[2]) <= 2;
            });
            if (!found) ++missing;
        }
    INFO(checked << " pixels, " << drawn.size() << " colours, " << missing << " not in the legend");
    CHECK(checked > 400);
    CHECK(drawn.size() > 20);
    CHECK(missing == 0);
}

TEST_CASE("render --legend: labs 04, 06 and 07 draw one, animate too, and a lab or setting whose colours are not data refuses", "[lab][labs]") {
    gsv::test::TempDir dir;
    for (const std::string lab : {"lab04_solution", "lab06_solution", "lab07_solution"}) {
        const auto run = gsv::test::render(lab, {}, dir.path(), lab, {"--legend"});
        INFO(run.process.output);
        CHECK(run.exit_code() == 0);
        CHECK(gsv::read_png(run.png).width > 128 + 40);
    }
    const auto animated = gsv::test::run_lab("lab07_solution", {"animate", "--legend", "--count", "2", "--size", "64x64",
                                                                "--out-dir", dir.path("frames").string()}, dir.path());
    REQUIRE(animated.exit_code() == 0);
    CHECK(gsv::read_png(dir.path("frames/frame_0001.png")).width > 64 + 30);
    for (const auto& [lab, settings] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"lab01_solution", {}}, {"lab04_solution", {"coloring=plain"}}, {"lab06_solution", {"compositing=fhp"}}}) {
        const auto run = gsv::test::render(lab, settings, dir.path(), lab + "-none", {"--legend"});
        INFO(run.process.output);
        CHECK(run.exit_code() == 1);
        CHECK(contains(run.process.output, "has no legend"));
        CHECK_FALSE(fs::exists(run.png));
    }
}

TEST_CASE("render --legend: lab 05's speed colours, and none with color_by_speed off", "[lab][labs][gl43]") {
    gsv::test::TempDir dir;
    const auto run = gsv::test::render("lab05_solution", {"particles=4096"}, dir.path(), "speed", {"--legend"});
    INFO(run.process.output);
    CHECK(run.exit_code() == 0);
    CHECK(gsv::read_png(run.png).width > 128 + 40);
    const auto off = gsv::test::render("lab05_solution", {"particles=4096", "color_by_speed=off"}, dir.path(), "off", {"--legend"});
    CHECK(off.exit_code() == 1);
}
