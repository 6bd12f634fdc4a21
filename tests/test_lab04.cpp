// Lab 04: the bump-mapped terrain's normals against the CPU's double-precision reference and the exact
// normals of procedural terrains, and its hard cases.
#include "catch.hpp"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "common/image/image.h"

#include <cstdlib>
#include <map>
#include <sstream>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

// The sweep's CSV as rows of column name -> text.
std::vector<std::map<std::string, std::string>> sweep(const std::vector<std::string>& settings, const fs::path& dir) {
    std::vector<std::string> args{"sweep", "--size", "64x48", "--frames", "1", "--warmup", "0", "--out-dir", dir.string()};
    for (const auto& s : settings) args.insert(args.end(), {"--set", s});
    const auto run = test::run_lab("lab04_solution", args, dir);
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const auto lines = test::lines_of(test::read_text(dir / "lab04-sweep.csv"));
    auto split = [](const std::string& line) {
        std::vector<std::string> cells;
        std::stringstream s(line);
        for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
        return cells;
    };
    const auto header = split(lines.at(0));
    std::vector<std::map<std::string, std::string>> rows;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto cells = split(lines[i]);
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < header.size() && k < cells.size(); ++k) row[header[k]] = cells[k];
        rows.push_back(row);
    }
    return rows;
}

double number(const std::map<std::string, std::string>& row, const std::string& column) { return std::stod(row.at(column)); }

}  // namespace

TEST_CASE("lab04: the shader's normals are the CPU's finite differences, borders included, on every terrain", "[lab][lab04]") {
    for (const std::string terrain : {"franke", "sin_cos", "jacksboro", "topobathy"}) {
        test::TempDir dir;
        std::vector<std::string> settings{"terrain=" + terrain, "exaggeration=4"};
        if (terrain == "franke" || terrain == "sin_cos") settings.push_back("grid=64");  // real terrains have their own
        const auto rows = sweep(settings, dir.path());
        REQUIRE(rows.size() == 5);  // delta 16, 8, 4, 2, 1
        // llvmpipe's bilinear weights are not exact at texel centres of a side that is not a power of two
        // (jacksboro's 403 x 344): 4e-3 degrees measured there, 4e-6 on the procedural 64 x 64.
        for (const auto& row : rows) {
            INFO(terrain << " delta " << row.at("delta"));
            CHECK(number(row, "gpu_vs_cpu_max_deg") < 0.01);
        }
    }
}

TEST_CASE("lab04: against exact normals, central differences converge at second order", "[lab][lab04]") {
    test::TempDir dir;
    const auto rows = sweep({"terrain=franke", "grid=256", "exaggeration=3"}, dir.path());
    REQUIRE(rows.size() == 5);
    // Mean error (the borders' one-sided samples are few): a quarter for each halving of the step.
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const double ratio = number(rows[i - 1], "normal_err_mean_deg") / number(rows[i], "normal_err_mean_deg");
        INFO("delta " << rows[i - 1].at("delta") << " -> " << rows[i].at("delta") << ": ratio " << ratio);
        CHECK(ratio > 3.0);
        CHECK(ratio < 4.5);
    }
    CHECK(number(rows.back(), "normal_err_mean_deg") < 0.02);
}

TEST_CASE("lab04: flat ground gives exactly up, and a huge exaggeration no NaN", "[lab][lab04]") {
    test::TempDir dir;
    const auto flat = sweep({"terrain=flat", "grid=32"}, dir.path());
    for (const auto& row : flat) CHECK(number(row, "normal_err_max_deg") == 0.0);
    test::TempDir steep;
    const auto huge = sweep({"terrain=franke", "grid=32", "exaggeration=100"}, steep.path());  // exit 4 on NaN
    for (const auto& row : huge) CHECK(number(row, "gpu_vs_cpu_max_deg") < 1e-3);
}

TEST_CASE("lab04: 8-bit heights terrace, and their normals stray far more than float heights'", "[lab][lab04]") {
    test::TempDir a, b;
    const auto floats = sweep({"terrain=franke", "grid=256", "exaggeration=3"}, a.path());
    const auto bytes = sweep({"terrain=franke", "grid=256", "exaggeration=3", "heights8=on"}, b.path());
    const double float_err = number(floats.back(), "normal_err_mean_deg");
    const double byte_err = number(bytes.back(), "normal_err_mean_deg");
    WARN("delta 1, mean normal error: float heights " << float_err << " deg, 8-bit heights " << byte_err << " deg");
    CHECK(byte_err > 20 * float_err);
}

TEST_CASE("lab04: a missing or corrupt elevation file gives one line naming it, status 1", "[lab][lab04]") {
    test::TempDir dir;
    const fs::path kit = dir.path("kit");
    fs::create_directories(kit / "solutions" / "lab04_terrain");
    fs::copy(test::source_root() / "shaders", kit / "shaders", fs::copy_options::recursive);
    fs::copy(test::source_root() / "solutions" / "lab04_terrain", kit / "solutions" / "lab04_terrain", fs::copy_options::recursive);
    fs::create_directories(kit / "data" / "terrain");
    dir.write("kit/data/terrain/topobathy.height", "GSVHEIGHT 1 120 91 2439.07 2431.554\nshort");
    for (const std::string terrain : {"jacksboro", "topobathy"}) {
        const auto run = test::render("lab04_solution", {"terrain=" + terrain}, dir.path(), "bad", {}, {"GSV_ROOT=" + kit.string()});
        INFO(run.process.output);
        CHECK(run.exit_code() == 1);
        CHECK(run.process.output.find(terrain == "jacksboro" ? "jacksboro_fault.height" : "topobathy.height") != std::string::npos);
        CHECK(!fs::exists(run.png));
    }
}

TEST_CASE("lab04: the starter paints the terrain magenta until the height colours are written", "[lab][lab04]") {
    test::TempDir dir;
    const auto run = test::render("lab04", {}, dir.path(), "starter");
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const Image image = read_png(run.png);
    CHECK(test::not_done_pixels(image) > image.width * image.height / 4);
}

TEST_CASE("lab04: the starter sweeps with the default plan, the knob's last value, and says it has none", "[lab][lab04]") {
    // The sweep plan (reference/lab04_terrain/sweep_plan.cpp) is linked into lab04_solution only: the starter's sweep
    // has the images' errors and times, no normals' columns, against delta=1 as the last value swept.
    test::TempDir dir;
    const auto run = test::run_lab("lab04", {"sweep", "--size", "32x24", "--frames", "1", "--warmup", "0", "--out-dir",
                                             dir.path().string()},
                                   dir.path());
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const auto lines = test::lines_of(test::read_text(dir.path("lab04-sweep.csv")));
    REQUIRE(lines.size() == 6);
    CHECK(lines[0].find("normal_err") == std::string::npos);
    CHECK(run.process.output.find("error against delta=1 (the last value swept; not shown converged: this build has no "
                                  "sweep plan") != std::string::npos);
}

TEST_CASE("sweep --knob sweeps any parameter through the values given, and refuses bad ones with status 2", "[lab][lab04]") {
    test::TempDir dir;
    const auto run = test::run_lab("lab04_solution", {"sweep", "--size", "64x48", "--frames", "1", "--warmup", "0",
                                                      "--set", "geometry=mesh", "--knob", "mesh_n", "--values", "2,16,64",
                                                      "--out-dir", dir.path().string()},
                                   dir.path());
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const auto lines = test::lines_of(test::read_text(dir.path("lab04-sweep.csv")));
    REQUIRE(lines.size() == 4);
    CHECK(lines[0].rfind("series,mesh_n,", 0) == 0);
    CHECK(lines[3].rfind("-,64,", 0) == 0);
    // A knob that is not the lab's own has no named reference: the last value, said not to be shown converged.
    CHECK(run.process.output.find("error against mesh_n=64 (the last value swept; not shown converged)") != std::string::npos);

    struct Bad {
        std::vector<std::string> args;
        std::string names;
    };
    for (const Bad& bad : {Bad{{"sweep", "--knob", "no_such"}, "unknown parameter 'no_such'"},
                           Bad{{"sweep", "--knob", "mesh_n", "--values", "2,5000"}, "'mesh_n' = 5000 is out of range"},
                           Bad{{"sweep", "--knob", "mesh_n", "--values", "8"}, "at least two values"},
                           Bad{{"sweep", "--values", "1,2"}, "--values needs --knob"},
                           Bad{{"render", "--knob", "delta"}, "for sweep mode"}}) {
        const auto refused = test::run_lab("lab04_solution", bad.args, dir.path());
        INFO(refused.process.output);
        CHECK(refused.exit_code() == 2);
        CHECK(refused.process.output.find(bad.names) != std::string::npos);
    }
}

TEST_CASE("lab04: a step far below one sample loses the normal to float32 cancellation", "[lab][lab04]") {
    test::TempDir dir;
    const auto run = test::run_lab("lab04_solution", {"sweep", "--size", "64x48", "--frames", "1", "--warmup", "0", "--set",
                                                      "terrain=franke", "--set", "grid=512", "--knob", "delta", "--values",
                                                      "0.0001,0.01,1", "--out-dir", dir.path().string()},
                                   dir.path());
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const auto lines = test::lines_of(test::read_text(dir.path("lab04-sweep.csv")));
    REQUIRE(lines.size() == 4);
    auto mean_error = [&](std::size_t row) {
        std::stringstream s(lines[row]);
        std::string cell;
        for (int k = 0; k <= 6; ++k) std::getline(s, cell, ',');  // normal_err_mean_deg
        return std::stod(cell);
    };
    // A whole sample: 0.0015 degrees; 1e-4: hundreds of times (measured 0.9 degrees on llvmpipe). 1e-2 depends on how
    // the texture unit weighs texels: llvmpipe in float, a few times a whole sample's error; a GPU with 8-bit
    // fractions of a texel rounds a 1/100 step to 2/256 or 3/256 (an NVIDIA H200 measured 2.85 degrees, and the 8-bit
    // stand-in GSV_TEXEL_SNAP=256 the same): on GPUs the normal is lost to the filter before float32 cancels it.
    CHECK(mean_error(3) < 0.01);
    CHECK(mean_error(2) < 5.0);
    CHECK(mean_error(1) > 100 * mean_error(3));
}

TEST_CASE("lab04: zoomed out, mipmapped heights come closer to a supersampled view than aliased ones", "[lab][lab04]") {
    test::TempDir dir;
    auto render = [&](const std::string& name, const std::string& size, std::vector<std::string> settings) {
        settings.insert(settings.end(), {"camera_distance=9", "camera_pitch=70", "coloring=plain", "exaggeration=6"});
        const auto run = test::render("lab04_solution", settings, dir.path(), name, {"--size", size});
        INFO(run.process.output);
        REQUIRE(run.exit_code() == 0);
        return read_png(run.png);
    };
    const Image aliased = render("aliased", "128x96", {});
    const Image mipmapped = render("mipmapped", "128x96", {"mipmaps=on"});
    // The reference: 8x8 samples per pixel, box-filtered.
    const Image fine = render("fine", "1024x768", {});
    double aliased_error = 0, mipmapped_error = 0;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 128; ++x)
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int j = 0; j < 8; ++j)
                    for (int i = 0; i < 8; ++i) sum += fine.at(8 * x + i, 8 * y + j)[c];
                const double reference = sum / 64;
                aliased_error += std::pow(aliased.at(x, y)[c] - reference, 2);
                mipmapped_error += std::pow(mipmapped.at(x, y)[c] - reference, 2);
            }
    aliased_error = std::sqrt(aliased_error / (128 * 96 * 3));
    mipmapped_error = std::sqrt(mipmapped_error / (128 * 96 * 3));
    WARN("RMSE against 8x8 supersampling: without mipmaps " << aliased_error << ", with " << mipmapped_error);
    CHECK(mipmapped_error < aliased_error);
}
