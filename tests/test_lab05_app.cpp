// Lab 05 as students and lecturers run it: the lab binary's render, animate and sweep modes, its refusals,
// and the particle buffers it hands the grader.
#include "common/gl/compute.h"
#include "common/image/image.h"
#include "common/image/image_compare.h"
#include "common/io/json.h"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "catch.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace gsv;

namespace {

std::vector<float> read_floats(const fs::path& file) {
    const std::string bytes = test::read_text(file);
    std::vector<float> out(bytes.size() / sizeof(float));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(float));
    return out;
}

std::string cell(const std::string& row, int k) {
    std::stringstream s(row);
    std::string text;
    for (int i = 0; i <= k; ++i) std::getline(s, text, ',');
    return text;
}

int column(const std::string& header, const std::string& name) {
    std::stringstream s(header);
    std::string text;
    for (int i = 0; std::getline(s, text, ','); ++i)
        if (text == name) return i;
    FAIL("no column " << name << " in " << header);
    return -1;
}

}  // namespace

TEST_CASE("lab05: on OpenGL 4.1 (macOS's) transform feedback steps the particles, and they are the compute path's", "[lab][lab05][gl43]") {
    test::TempDir dir;
    // Mesa's override makes the driver offer 4.1 core, as a Mac does: the lab asks for 4.1 and holds to what it gets.
    const std::vector<std::string> settings{"particles=1000", "field=abc", "integrator=rk4", "time=1"};
    const auto at41 = test::render("lab05_solution", settings, dir.path(), "gl41", {"--arrays"},
                                   {"MESA_GL_VERSION_OVERRIDE=4.1", "MESA_GLSL_VERSION_OVERRIDE=410"});
    INFO(at41.process.output);
    REQUIRE(at41.exit_code() == 0);
    const Json report = read_json_file(at41.json);
    CHECK(report.object_at("gl").string_at("effective") == "4.1");
    CHECK(report.object_at("gl").string_at("profile") == "core");
    // On the same driver at 4.5 the lab holds to 4.3 and dispatches its compute shader.
    const auto at43 = test::render("lab05_solution", settings, dir.path(), "gl43", {"--arrays"});
    REQUIRE(at43.exit_code() == 0);
    CHECK(read_json_file(at43.json).object_at("gl").string_at("effective") == "4.3");
    for (const char* array : {"positions", "velocities"}) {
        INFO(array);
        const std::vector<float> captured = read_floats(dir.path(std::string("gl41.") + array + ".f32"));
        const std::vector<float> computed = read_floats(dir.path(std::string("gl43.") + array + ".f32"));
        REQUIRE(captured.size() == computed.size());
        CHECK(std::memcmp(captured.data(), computed.data(), captured.size() * sizeof(float)) == 0);
    }
    CHECK(compare_images(read_png(at41.png), read_png(at43.png), {}).max_channel_diff == 0);
    // --gl 4.1 holds a 4.5 driver to 4.1 too: local_size then acts through nothing, and a setting of it is not refused.
    const auto held = test::render("lab05_solution", {"particles=1000", "local_size=64"}, dir.path(), "held", {"--gl", "4.1"});
    INFO(held.process.output);
    CHECK(held.exit_code() == 0);
    CHECK(read_json_file(held.json).object_at("gl").string_at("effective") == "4.1");
}

TEST_CASE("lab05: settings that cannot go together or out of range give one line naming them", "[lab][lab05][gl43]") {
    test::TempDir dir;
    auto run = test::render("lab05_solution", {"field=gravity", "source=texture"}, dir.path(), "bad");
    CHECK(run.exit_code() == 1);
    CHECK(run.process.output.find("source=texture samples a velocity field; field=gravity has none") != std::string::npos);
    CHECK_FALSE(fs::exists(run.png));
    run = test::render("lab05_solution", {"local_size=2048"}, dir.path(), "bad");
    CHECK(run.exit_code() == 2);
    CHECK(run.process.output.find("local_size") != std::string::npos);
    run = test::render("lab05_solution", {"particles=0"}, dir.path(), "bad");
    CHECK(run.exit_code() == 2);
    CHECK(run.process.output.find("particles") != std::string::npos);
}

TEST_CASE("lab05: particles past this GPU's storage blocks are refused in bytes and MiB that differ, and a sweep of nothing else exits unsupported", "[lab][lab05][gl43]") {
    std::int64_t limit = 0;
    {
        const auto context = test::headless_context(Profile::Core, {4, 3});
        limit = compute_limits().max_storage_block_bytes;
    }
    // As many particles as the limit holds origins (32 bytes each): their sentinel slots take the buffer past it.
    const std::int64_t count = limit / 32;
    if (count > 16777216) {
        WARN("this GPU's storage blocks hold " << limit << " bytes: more origins than the lab's 16,777,216 particles, so none is refused");
        return;
    }
    test::TempDir dir;
    const auto run = test::run_lab("lab05_solution", {"sweep", "--size", "16x16", "--frames", "1", "--warmup", "0", "--set",
                                                      "particles=" + std::to_string(count), "--knob", "local_size", "--values",
                                                      "1,1024", "--out-dir", dir.path("sweep").string()},
                                   dir.path());
    INFO(run.process.output);
    CHECK(run.exit_code() == 3);  // unsupported: what this device cannot do, not a failure
    const std::regex refusal("lab05: every setting of the sweep was left out; the first: particles=" + std::to_string(count) +
                             R"( needs a storage buffer of (\d+) bytes \((\d+\.\d\d) MiB\) for (\d+) origins of 32 bytes, the )"
                             R"(sentinel slots included; this GPU allows (\d+) bytes \((\d+\.\d\d) MiB\)\n)");
    std::smatch m;
    REQUIRE(std::regex_search(run.process.output, m, refusal));
    const std::int64_t needed = std::stoll(m[1]), origins = std::stoll(m[3]), allowed = std::stoll(m[4]);
    CHECK(needed == origins * 32);
    CHECK(origins > count);
    CHECK(allowed == limit);
    CHECK(needed > allowed);
    auto mib = [](std::int64_t bytes) {
        char text[32];
        std::snprintf(text, sizeof text, "%.2f", static_cast<double>(bytes) / (1 << 20));
        return std::string(text);
    };
    CHECK(m[2] == mib(needed));
    CHECK(m[5] == mib(allowed));
    CHECK(m[2] != m[5]);  // the sizes differ as printed, not only in bytes
}

TEST_CASE("lab05: the buffers handed to the grader hold every particle and the untouched sentinels past them", "[lab][lab05][gl43]") {
    test::TempDir dir;
    const auto plain = test::render("lab05_solution", {"particles=1000", "local_size=64"}, dir.path(), "plain");
    REQUIRE(plain.exit_code() == 0);
    CHECK_FALSE(fs::exists(dir.path("plain.positions.f32")));  // only when asked: they can be large
    const auto run = test::render("lab05_solution", {"particles=1000", "local_size=64"}, dir.path(), "ragged", {"--arrays"});
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const std::vector<float> positions = read_floats(dir.path("ragged.positions.f32"));
    const std::vector<float> velocities = read_floats(dir.path("ragged.velocities.f32"));
    REQUIRE(positions.size() == 1024 * 4);  // 1000 particles, one block of 1024 slots
    REQUIRE(velocities.size() == 1024 * 4);
    for (std::size_t i = 0; i < 1000; ++i) {
        CHECK(positions[4 * i + 3] == 1.0f);
        for (int k = 0; k < 3; ++k) CHECK(std::abs(positions[4 * i + k]) <= 1.0f);
    }
    for (std::size_t i = 1000; i < 1024; ++i) {
        CHECK(positions[4 * i] == 0.3f);
        CHECK(positions[4 * i + 1] == 0.6f);
        CHECK(positions[4 * i + 3] == 0.0f);
        CHECK(velocities[4 * i] == 0.0f);
    }
}

TEST_CASE("lab05: the starter draws its particles magenta, unmoved, until its TODOs are done", "[lab][lab05][gl43]") {
    test::TempDir dir;
    const auto run = test::render("lab05", {"particles=65536"}, dir.path(), "starter");
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const Image image = read_png(run.png);
    CHECK(test::not_done_pixels(image) > image.width * image.height / 10);
}

TEST_CASE("lab05: animate carries the particles on from frame to frame and gives what a render at that time gives", "[lab][lab05][gl43]") {
    test::TempDir dir;
    const fs::path out = dir.path("anim");
    const auto run = test::run_lab("lab05_solution", {"animate", "--size", "96x96", "--count", "3", "--from", "0", "--to", "1.5",
                                                      "--set", "particles=8192", "--out-dir", out.string()},
                                   dir.path());
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    for (int k = 0; k < 3; ++k) {
        const std::string time = k == 0 ? "0" : k == 1 ? "0.5" : "1";  // frame k at k / count of the span
        const auto still = test::render("lab05_solution", {"particles=8192", "time=" + time}, dir.path(), "t" + std::to_string(k),
                                        {"--size", "96x96"});
        REQUIRE(still.exit_code() == 0);
        INFO("frame " << k);
        CHECK(read_png(still.png).rgba == read_png(out / ("frame_000" + std::to_string(k) + ".png")).rgba);
    }
    CHECK(read_png(out / "frame_0000.png").rgba != read_png(out / "frame_0002.png").rgba);
}

TEST_CASE("lab05: the sweep measures each integrator's order against the double-precision reference, and both speeds", "[lab][lab05][gl43]") {
    test::TempDir dir;
    const auto run = test::run_lab("lab05_solution", {"sweep", "--size", "64x64", "--frames", "1", "--warmup", "0", "--set",
                                                      "particles=2048", "--set", "time=1.6", "--out-dir", dir.path().string()},
                                   dir.path());
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const auto rows = test::lines_of(test::read_text(dir.path("lab05-sweep.csv")));
    REQUIRE(rows.size() == 1 + 3 * 5);  // header, 3 integrators x 5 steps
    const int err = column(rows[0], "pos_err_rms"), gpu = column(rows[0], "gpu_Mparticles_s"),
              cpu = column(rows[0], "cpu_Mparticles_s"), gap = column(rows[0], "gpu_vs_cpu_max"),
              followed = column(rows[0], "followed"), steps = column(rows[0], "steps");
    auto value = [&](int row, int col) { return std::stod(cell(rows[row], col)); };
    for (int r = 1; r <= 15; ++r) {
        INFO(rows[r]);
        CHECK(value(r, gpu) > 0);
        CHECK(value(r, cpu) > 0);
        CHECK(value(r, gap) < 1e-4);  // the GPU does the CPU's float update
        CHECK(value(r, followed) > 100);
    }
    CHECK(value(1, steps) == 4);   // 1.6 / 0.4: the same simulated time in every row
    CHECK(value(5, steps) == 64);
    // Halving h: Euler's error halves, the midpoint rule's quarters, RK4's falls sixteenfold until float
    // rounding (about 1e-6 here) is all that is left.
    for (int r = 1; r < 5; ++r) {
        INFO(rows[r] << "\n" << rows[r + 1]);
        CHECK(value(r, err) / value(r + 1, err) == Approx(2).margin(0.5));
        CHECK(value(r + 5, err) / value(r + 6, err) == Approx(4).margin(1.2));
    }
    CHECK(value(11, err) / value(12, err) > 10);
    CHECK(value(12, err) / value(13, err) > 10);
    CHECK(value(15, err) < 2e-6);
    // The plot shows that error, not the image's RMSE, which restarts at step-dependent times swamp: the share of
    // particles that left the domain says how many.
    CHECK(test::read_text(dir.path("lab05-sweep.gp")).find("set ylabel 'pos_err_rms, against the reference'") != std::string::npos);
    const int left = column(rows[0], "left_share");
    CHECK(value(15, left) > 0.1);
    CHECK(value(15, left) == Approx(1.0 - value(15, followed) / 2048.0));
    // No rotation, no radii.
    CHECK(rows[0].find("radius_ratio") == std::string::npos);
}

TEST_CASE("lab05: on the rotation the sweep shows each integrator's radius after a turn beside its closed form", "[lab][lab05][gl43]") {
    test::TempDir dir;
    const auto run = test::run_lab("lab05_solution", {"sweep", "--size", "48x48", "--frames", "1", "--warmup", "0", "--set",
                                                      "particles=1024", "--set", "field=rotation", "--set", "time=6.3", "--knob",
                                                      "time_step", "--values", "0.2,0.1", "--out-dir", dir.path().string()},
                                   dir.path());
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const auto rows = test::lines_of(test::read_text(dir.path("lab05-sweep.csv")));
    REQUIRE(rows.size() == 1 + 3 * 2);
    const std::string& header = rows[0];
    // Euler, midpoint, RK4 at h = 0.1, 63 steps: the lab sheet's 1.368, 1.0008 and 0.9999996.
    const double expected[] = {1.368, 1.0008, 0.9999996};
    for (int m = 0; m < 3; ++m) {
        const std::string& row = rows[2 + 2 * m];
        INFO(row);
        CHECK(test::csv_value(header, row, "radius_ratio_closed_form") == Approx(expected[m]).margin(5e-4));
        // The GPU's particles, in float, do what the closed form says.
        CHECK(test::csv_value(header, row, "radius_ratio") == Approx(test::csv_value(header, row, "radius_ratio_closed_form")).epsilon(1e-4));
    }
}
