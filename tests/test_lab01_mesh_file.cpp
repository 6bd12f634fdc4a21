// Lab 01 draws any OBJ (model=file, mesh_file=PATH): a quad exported without normals draws, and what cannot be
// drawn is refused with one line naming the file (and line) and a non-zero exit.
#include "common/image/image.h"
#include "lab_runner.h"
#include "test_support.h"

#include "catch.hpp"

namespace fs = std::filesystem;
using namespace gsv;

TEST_CASE("lab01: model=file draws any OBJ, and a missing or broken one is named in one line", "[lab][lab01]") {
    test::TempDir dir;
    // Two quads (one folded) with no normals: the reader computes them; the camera frames it like the sphere.
    const fs::path quads = dir.write("quads.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv 0 -1 -1\nv 0 1 -1\n"
                                                  "f 1 2 3 4\nf 1 4 6 5\n");
    const auto drawn = test::render("lab01_solution", {"model=file", "mesh_file=" + quads.string()}, dir.path(), "quads");
    INFO(drawn.process.output);
    REQUIRE(drawn.exit_code() == 0);
    const auto sphere = test::render("lab01_solution", {}, dir.path(), "sphere");
    REQUIRE(sphere.exit_code() == 0);
    CHECK(read_png(drawn.png).rgba != read_png(sphere.png).rgba);

    const auto none = test::render("lab01_solution", {"model=file"}, dir.path(), "none");
    CHECK(none.exit_code() != 0);
    CHECK(none.process.output.find("model=file needs mesh_file=PATH") != std::string::npos);
    const fs::path broken = dir.write("broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1x 0\nf 1 2 3\n");
    const auto bad = test::render("lab01_solution", {"model=file", "mesh_file=" + broken.string()}, dir.path(), "bad");
    CHECK(bad.exit_code() != 0);
    CHECK(bad.process.output.find("broken.obj:3: malformed number '1x'") != std::string::npos);
    CHECK_FALSE(fs::exists(bad.png));
    // Without model=file the file would change nothing: refused, naming what enables it.
    const auto ignored = test::render("lab01_solution", {"mesh_file=" + quads.string()}, dir.path(), "ignored");
    CHECK(ignored.exit_code() == 2);
    CHECK(ignored.process.output.find("it needs model=file") != std::string::npos);
}
