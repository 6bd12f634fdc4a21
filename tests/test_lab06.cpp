// Lab 06 as students and lecturers run it: its network (in code and from files), the visual debugging
// images, the camera inside the volume, clipping everything away, the errors a processor reports, and the
// sweep against the analytic Marschner-Lobb isosurface.
#include "common/image/image.h"
#include "common/image/image_compare.h"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "catch.hpp"

#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace gsv;

namespace {

const std::string kLab = "lab06_solution";

double rmse(const fs::path& a, const fs::path& b) { return compare_images(read_png(a), read_png(b), ImageTolerance{}).rmse; }

// Pixels equal to the canvas's default background (0.08, 0.09, 0.12) within rounding.
int background_pixels(const Image& image) {
    int count = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
        count += std::abs(image.rgba[i] - 20) <= 1 && std::abs(image.rgba[i + 1] - 23) <= 1 && std::abs(image.rgba[i + 2] - 31) <= 1;
    return count;
}

}  // namespace

TEST_CASE("lab06: the network built in code draws what raycast.network and probe.network draw", "[lab][lab06]") {
    test::TempDir dir;
    const auto code = test::render(kLab, {}, dir.path(), "code");
    const auto file = test::render(kLab, {"network=raycast.network"}, dir.path(), "file");
    const auto probe_code = test::render(kLab, {"probe=on"}, dir.path(), "probe_code");
    const auto probe_file = test::render(kLab, {"network=probe.network"}, dir.path(), "probe_file");
    for (const auto* run : {&code, &file, &probe_code, &probe_file}) {
        INFO(run->process.output);
        REQUIRE(run->exit_code() == 0);
    }
    CHECK(rmse(code.png, file.png) == 0.0);
    CHECK(rmse(probe_code.png, probe_file.png) == 0.0);
    CHECK(rmse(code.png, probe_code.png) > 1.0);  // the probe shows
}

TEST_CASE("lab06: a property a network file sets wins over the parameter of that name", "[lab][lab06]") {
    test::TempDir dir;
    std::string text = test::read_text(test::source_root() / "solutions" / "lab06_raycasting" / "raycast.network");
    const auto at = text.find("processor RayTraversal raycaster");
    REQUIRE(at != std::string::npos);
    text.insert(at + std::string("processor RayTraversal raycaster").size(), " compositing=mip classification=raw");
    const fs::path network = dir.write("mip.network", text);
    const auto from_file = test::render(kLab, {"network=" + network.string(), "compositing=dvr"}, dir.path(), "file");
    const auto mip = test::render(kLab, {"compositing=mip", "classification=raw"}, dir.path(), "mip");
    INFO(from_file.process.output);
    REQUIRE(from_file.exit_code() == 0);
    REQUIRE(mip.exit_code() == 0);
    CHECK(rmse(from_file.png, mip.png) == 0.0);
}

TEST_CASE("lab06: render --debug-images writes every port's colour, alpha and depth, named by processor", "[lab][lab06]") {
    test::TempDir dir;
    const auto run = test::render(kLab, {"probe=on"}, dir.path(), "probe", {"--debug-images"});
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const fs::path debug = dir.path("probe-debug");
    for (const std::string port : {"entry_exit.entry", "entry_exit.exit", "raycaster.image", "probe_renderer.image", "canvas.image"})
        for (const std::string kind : {".png", ".alpha.png", ".depth.png"}) {
            INFO(port + kind);
            CHECK(fs::exists(debug / (port + kind)));
        }
    // The entry points are texture coordinates: at the centre the ray enters the box somewhere inside
    // [0, 1]^3, alpha 1; in a corner no ray, alpha 0. The canvas is the image itself.
    const Image entry = read_png(debug / "entry_exit.entry.png");
    CHECK(entry.at(64, 64)[3] == 255);
    CHECK(entry.at(0, 0)[3] == 0);
    CHECK(rmse(debug / "canvas.image.png", run.png) == 0.0);
    // The exit points differ from the entry points wherever a ray has length.
    CHECK(rmse(debug / "entry_exit.entry.png", debug / "entry_exit.exit.png") > 10.0);
}

TEST_CASE("lab06: with the camera inside the volume every pixel has a ray, from the near plane", "[lab][lab06]") {
    test::TempDir dir;
    const auto inside = test::render(kLab, {"camera_distance=0.3", "transfer_function=grey"}, dir.path(), "inside");
    const auto outside = test::render(kLab, {"transfer_function=grey"}, dir.path(), "outside");
    INFO(inside.process.output);
    REQUIRE(inside.exit_code() == 0);
    REQUIRE(outside.exit_code() == 0);
    CHECK(background_pixels(read_png(outside.png)) > 1000);  // the test can tell background from volume
    CHECK(background_pixels(read_png(inside.png)) == 0);
}

TEST_CASE("lab06: a clipping plane that removes the whole volume leaves the background, and the rays follow a cut", "[lab][lab06]") {
    test::TempDir dir;
    const auto gone = test::render(kLab, {"clip_normal=1,0,0", "clip_offset=-0.9"}, dir.path(), "gone");
    INFO(gone.process.output);
    REQUIRE(gone.exit_code() == 0);
    CHECK(background_pixels(read_png(gone.png)) == 128 * 128);
    const auto half = test::render(kLab, {"clip_normal=1,0,0", "clip_offset=0"}, dir.path(), "half");
    const auto whole = test::render(kLab, {}, dir.path(), "whole");
    REQUIRE(half.exit_code() == 0);
    CHECK(background_pixels(read_png(half.png)) > background_pixels(read_png(whole.png)) + 500);
}

TEST_CASE("lab06: a constant volume (zero gradient) and an iso value equal to it draw no NaN", "[lab][lab06]") {
    test::TempDir dir;
    for (const std::string compositing : {"dvr", "iso"}) {
        std::vector<std::string> settings{"volume=constant", "compositing=" + compositing};
        if (compositing == "iso") settings.push_back("iso_value=0.5");  // the constant's own value
        const auto run = test::render(kLab, settings, dir.path(), compositing);
        INFO(run.process.output);
        REQUIRE(run.exit_code() == 0);
        const std::string json = test::read_text(run.json);
        CHECK(json.find("\"nan_pixels\": 0") != std::string::npos);
        CHECK(json.find("\"blank\": false") != std::string::npos);
    }
}

TEST_CASE("lab06: a broken shader stops the run with one line naming the processor that owns it and the file", "[lab][lab06]") {
    test::TempDir dir;
    const fs::path root = dir.path("kit");
    test::copy_lab_kit(test::source_root(), root, "lab06_raycasting");
    test::replace_in_file(root / "solutions" / "lab06_raycasting" / "composite_mip.glsl", "s.value = intensity;", "s.value = intensity");
    const auto run = test::render(kLab, {"compositing=mip"}, dir.path(), "broken", {}, {"GSV_ROOT=" + root.string()});
    INFO(run.process.output);
    CHECK(run.exit_code() == 1);
    CHECK(run.process.output.find("raycaster: ") != std::string::npos);
    CHECK(run.process.output.find("composite_mip.glsl:") != std::string::npos);
    CHECK_FALSE(fs::exists(run.png));
    // DVR does not compile the MIP module: the same kit draws it.
    const auto dvr = test::render(kLab, {}, dir.path(), "dvr", {}, {"GSV_ROOT=" + root.string()});
    INFO(dvr.process.output);
    CHECK(dvr.exit_code() == 0);
}

TEST_CASE("lab06: bad settings, network files and volumes give one line naming them, and no image", "[lab][lab06]") {
    test::TempDir dir;
    struct Bad {
        std::vector<std::string> settings;
        std::string says;
    };
    const fs::path bad_network = dir.write("bad.network", "processor VolumeSource source\nprocessor Raycaster r\n");
    const fs::path open_network = dir.write("open.network", "processor VolumeSource source\nprocessor RayTraversal raycaster\n");
    const fs::path bad_value = dir.write("value.network", "processor RayTraversal raycaster samples_per_voxel=lots\n"
                                                         "processor VolumeSource source\nprocessor ProxySource proxy\n"
                                                         "processor EntryExitPoints entry_exit\nprocessor Canvas canvas\n"
                                                         "connect source.volume -> proxy.volume\nconnect proxy.geometry -> entry_exit.proxy\n"
                                                         "connect source.volume -> raycaster.volume\nconnect entry_exit.entry -> raycaster.entry\n"
                                                         "connect entry_exit.exit -> raycaster.exit\nconnect raycaster.image -> canvas.image\n");
    const fs::path not_nifti = dir.write("head.nii", std::string(400, 'x'));
    const std::vector<Bad> cases = {
        {{"shading=phong", "gradient=none"}, "needs a gradient for its normal"},
        {{"shader=handwritten", "compositing=mip"}, "raycaster.shader = 'handwritten' draws only compositing dvr"},
        {{"network=" + bad_network.string()}, "bad.network:2: "},
        {{"network=" + open_network.string()}, "are not connected"},
        {{"network=" + bad_value.string()}, "parameter 'samples_per_voxel' = 'lots' is not a number"},
        {{"volume=file"}, "volume=file needs volume_file=PATH"},
        {{"volume=file", "volume_file=" + not_nifti.string()}, "head.nii"},
        {{"samples_per_voxel=0"}, "samples_per_voxel"},
    };
    for (const auto& c : cases) {
        const auto run = test::render(kLab, c.settings, dir.path(), "bad");
        INFO(run.process.output);
        CHECK(run.exit_code() != 0);
        CHECK(run.process.output.find(c.says) != std::string::npos);
        CHECK_FALSE(fs::exists(run.png));
    }
}

TEST_CASE("lab06: samples_per_voxel out of range is the same one line from the command line, a case file and a network file", "[lab][lab06]") {
    // Declared once, by the ray caster (ray_traversal.cpp): one range and one parser (Params::set) wherever it is set.
    const std::string says = "parameter 'samples_per_voxel' = 100 is out of range [0.05, 32]";
    test::TempDir dir;
    const fs::path root = dir.path("kit");
    test::copy_lab_kit(test::source_root(), root, "lab06_raycasting");
    const fs::path cases = root / "grader" / "cases" / "lab06.json";
    fs::create_directories(cases.parent_path());
    std::string text = test::read_text(test::source_root() / "grader" / "cases" / "lab06.json");
    const std::string from = "\"samples_per_voxel=4\"";
    REQUIRE(text.find(from) != std::string::npos);
    text.replace(text.find(from), from.size(), "\"samples_per_voxel=100\"");
    std::ofstream(cases) << text;
    std::string network = test::read_text(test::source_root() / "solutions" / "lab06_raycasting" / "raycast.network");
    const std::string raycaster = "processor RayTraversal raycaster";
    REQUIRE(network.find(raycaster) != std::string::npos);
    network.insert(network.find(raycaster) + raycaster.size(), " samples_per_voxel=100");
    const fs::path network_file = dir.write("far.network", network);
    const std::vector<std::string> env{"GSV_ROOT=" + root.string()};
    const std::vector<std::pair<std::string, test::LabRun>> runs = {
        {"command line", test::render(kLab, {"samples_per_voxel=100"}, dir.path(), "cli", {}, env)},
        {"case file", test::run_lab(kLab, {"render", "--case", "corrected", "--out", "case.png"}, dir.path(), env)},
        {"network file", test::render(kLab, {"network=" + network_file.string()}, dir.path(), "network", {}, env)},
    };
    for (const auto& [where, run] : runs) {
        INFO(where << ": " << run.process.output);
        CHECK(run.exit_code() != 0);
        CHECK(run.process.output.find(says) != std::string::npos);
        // One line: the message ends its line, and no other line speaks of the parameter.
        const std::string& out = run.process.output;
        const std::size_t at = out.find(says);
        CHECK((at == std::string::npos || at + says.size() == out.size() || out[at + says.size()] == '\n'));
        CHECK(out.find("samples_per_voxel") == at + std::string("parameter '").size());
        CHECK(out.find("samples_per_voxel", at + says.size()) == std::string::npos);
    }
}

TEST_CASE("lab06: the starter draws the box magenta until the compositing is written", "[lab][lab06]") {
    test::TempDir dir;
    const auto run = test::render("lab06", {}, dir.path(), "starter");
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    CHECK(test::not_done_pixels(read_png(run.png)) > 128 * 128 / 4);
}

TEST_CASE("lab06: the sweep measures hits against the exact isosurface, and sampling more brings them closer", "[lab][lab06]") {
    test::TempDir dir;
    const auto run = test::run_lab(kLab, {"sweep", "--size", "96x96", "--frames", "1", "--warmup", "0", "--set", "compositing=iso",
                                          "--knob", "samples_per_voxel", "--values", "0.25,4", "--set", "compare_shaders=on",
                                          "--out-dir", dir.path("sweep").string()},
                                   dir.path());
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    std::stringstream csv(test::read_text(dir.path("sweep") / "lab06-sweep.csv"));
    std::string header, coarse, fine;
    std::getline(csv, header);
    std::getline(csv, coarse);
    std::getline(csv, fine);
    auto value = [&](const std::string& row, const std::string& name) { return test::csv_value(header, row, name); };
    CHECK(value(coarse, "iso_err_rms") > 1.1 * value(fine, "iso_err_rms"));
    CHECK(value(fine, "iso_err_rms") < 0.2);
    CHECK(value(fine, "iso_missed") < 0.2);
    CHECK(value(fine, "normal_err_deg") > 0.0);
    CHECK(value(fine, "specialised_ms") > 0.0);
    CHECK(value(fine, "uber_ms") > 0.0);
}

TEST_CASE("lab06: the default camera frames the whole volume from any side, and fills a good part of the image", "[lab][lab06]") {
    // A constant volume fills its whole box: through the grey transfer function every ray that meets the box shows.
    test::TempDir dir;
    const std::vector<std::vector<std::string>> views = {
        {}, {"camera_yaw=45", "camera_pitch=35.26"}, {"camera_yaw=90", "camera_pitch=0"}, {"camera_yaw=-135", "camera_pitch=-35"}};
    for (std::size_t v = 0; v < views.size(); ++v) {
        std::vector<std::string> settings = views[v];
        settings.push_back("volume=constant");
        settings.push_back("transfer_function=grey");
        const auto run = test::render(kLab, settings, dir.path(), "view" + std::to_string(v));
        INFO(run.process.output);
        REQUIRE(run.exit_code() == 0);
        const Image image = read_png(run.png);
        int border = 0, volume = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const std::uint8_t* p = image.at(x, y);
                const bool background = std::abs(p[0] - 20) <= 1 && std::abs(p[1] - 23) <= 1 && std::abs(p[2] - 31) <= 1;
                volume += !background;
                if (x == 0 || y == 0 || x == image.width - 1 || y == image.height - 1) border += !background;
            }
        INFO("view " << v << ": " << border << " volume pixels on the image's edge, " << volume << " in all");
        CHECK(border == 0);
        CHECK(volume > image.width * image.height / 5);
    }
}

TEST_CASE("lab06: the MRI brain shows its tissues, the ventricles blue and the white matter cream, by DVR and MIP", "[lab][lab06]") {
    // Before the scan was windowed its tissue filled [0.17, 0.45] of the normalised range: a dim brown blur (the
    // head and mip-head goldens then had no pixel blue or cream, and a mean of 41 and 28 over the volume's pixels).
    test::TempDir dir;
    struct Shares {
        double blue = 0, cream = 0, mean = 0;
    };
    const auto shares = [&](const std::string& name, const std::vector<std::string>& settings) {
        const auto run = test::render(kLab, settings, dir.path(), name);
        INFO(run.process.output);
        REQUIRE(run.exit_code() == 0);
        const Image image = read_png(run.png);
        Shares s;
        int volume = 0;
        for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
            const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
            if (std::abs(r - 20) <= 1 && std::abs(g - 23) <= 1 && std::abs(b - 31) <= 1) continue;
            ++volume;
            s.blue += b > r + 40;
            s.cream += r > 120 && r >= b;
            s.mean += 0.2126 * r + 0.7152 * g + 0.0722 * b;
        }
        REQUIRE(volume > 0);
        s.blue /= volume, s.cream /= volume, s.mean /= volume;
        return s;
    };
    const std::vector<std::string> brain = {"volume=anatomical", "transfer_function=tissue", "camera_distance=4.2"};
    std::vector<std::string> dvr = brain, mip = brain;
    dvr.insert(dvr.end(), {"camera_yaw=60", "camera_pitch=10"});
    mip.insert(mip.end(), {"compositing=mip", "camera_yaw=90", "camera_pitch=0"});
    const Shares d = shares("dvr", dvr), m = shares("mip", mip);
    INFO("DVR: " << d.blue << " blue, " << d.cream << " cream, mean " << d.mean << "; MIP: " << m.cream << " cream, mean " << m.mean);
    CHECK(d.blue > 0.1);
    CHECK(d.cream > 0.1);
    CHECK(d.mean > 70);
    CHECK(m.cream > 0.1);
    CHECK(m.mean > 60);
}
