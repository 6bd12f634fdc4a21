// Lab 01's back faces: shade.frag flips a back face's normal to face the eye, which is right for a back face that
// is seen (the inside of a cut-open model) and wrong for one that only wins a depth tie along a silhouette, where
// the flipped normal points to the other side of the rim. A kit whose fragment stage paints back faces green shows
// which faces won.
#include "common/image/image.h"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "catch.hpp"

#include <string>
#include <vector>

using namespace gsv;

namespace {

int green_pixels(const Image& image) {
    int count = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
        count += image.rgba[i] == 0 && image.rgba[i + 1] == 255 && image.rgba[i + 2] == 0;
    return count;
}

}  // namespace

TEST_CASE("lab01: no back face wins a depth tie along a closed model's silhouette, and a cut still shows its back faces", "[lab][lab01]") {
    namespace fs = std::filesystem;
    test::TempDir dir;
    const fs::path root = dir.path("kit");
    test::copy_lab_kit(test::source_root(), root, "lab01_gooch");
    fs::copy(test::source_root() / "data" / "meshes", root / "data" / "meshes", fs::copy_options::recursive);
    test::replace_in_file(root / "solutions" / "lab01_gooch" / "shade.frag", "    fColor = vec4(color, 1.0);",
                          "    fColor = gl_FrontFacing ? vec4(color, 1.0) : vec4(0.0, 1.0, 0.0, 1.0);");
    const auto back_faces_seen = [&](const std::vector<std::string>& settings, const std::string& name) {
        const auto run = test::render("lab01_solution", settings, dir.path(), name, {"--size", "512x512"}, {"GSV_ROOT=" + root.string()});
        INFO(run.process.output);
        REQUIRE(run.exit_code() == 0);
        return green_pixels(read_png(run.png));
    };
    // The default sphere drawn in one pass showed one back-face pixel on its rim; these views and meshes none.
    const std::vector<std::vector<std::string>> closed = {
        {}, {"mesh_resolution=24"}, {"camera_yaw=-70", "camera_pitch=-30"}, {"model=torus", "camera_pitch=50"},
        {"scale=1.3,0.6,1", "camera_distance=4"}};
    for (std::size_t i = 0; i < closed.size(); ++i) {
        INFO("closed model, settings " << i);
        CHECK(back_faces_seen(closed[i], "closed" + std::to_string(i)) == 0);
    }
    CHECK(back_faces_seen({"cut=0.25", "camera_yaw=70"}, "cut") > 10000);
}
