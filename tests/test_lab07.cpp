// Lab 07 on the GPU and as students run it: the per-fragment evaluation (spectral.glsl) exactly at the
// nodes and a float ulp beside them, against the double-precision reference; the sweep's error floor and
// its Runge blow-up; the starter's "not done" image; and the refusals.
#include "catch.hpp"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "common/gl/buffer_texture.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/image/image.h"
#include "common/shader/shader_program.h"
#include "reference/spectral/lagrange_basis.h"
#include "support/spectral/lagrange.h"
#include "support/spectral/spectral_mesh.h"

#include <cmath>
#include <map>
#include <sstream>

namespace fs = std::filesystem;
using namespace gsv;

namespace {

const fs::path kLab07 = test::source_root() / "solutions" / "lab07_spectral";

struct NodeProbe {
    std::vector<double> nodes, weights;
    std::vector<float> values;
    ImageF image;  // row 0 = top
};

NodeProbe probe_at_nodes(NodeSet set, int degree) {
    auto context = test::headless_context();
    NodeProbe r;
    r.nodes = lagrange_nodes(set, degree);
    r.weights = barycentric_weights(r.nodes);
    ElementMesh mesh;
    mesh.shape = ElementMesh::Shape::Grid;
    mesh.columns = mesh.rows = 1;
    r.values = sample_element_values(mesh, SpectralField::Runge, r.nodes, 0);
    ProgramSpec spec;
    spec.name = "lagrange_at_nodes";
    spec.files = {test::source_root() / "shaders" / "gsv" / "fullscreen.vert", test::test_shader("lagrange_at_nodes.frag")};
    spec.defines = {{"DEGREE", std::to_string(degree)}};
    PreprocessOptions options;
    options.version = context->effective_version();
    options.include_dirs = {kLab07, test::source_root() / "shaders"};
    const ShaderProgram program = ShaderProgram::build(spec, options);
    const std::vector<float> x(r.nodes.begin(), r.nodes.end()), w(r.weights.begin(), r.weights.end());
    const BufferTexture values = BufferTexture::create_r32f(r.values.data(), r.values.size());
    const GpuMesh quad(make_fullscreen_quad(), Profile::Core);
    Framebuffer target(degree + 1, degree + 2, ColorFormat::RGBA32F, false);
    target.bind();
    program.use();
    glUniform1fv(program.location("uNodes[0]"), static_cast<GLsizei>(x.size()), x.data());
    glUniform1fv(program.location("uWeights[0]"), static_cast<GLsizei>(w.size()), w.data());
    values.bind(1);
    program.set("uValues", 1);
    program.set("uTrianglesPerElement", 2);
    quad.draw();
    r.image = target.read_rgba32f();
    check_gl_error("probing the basis at the nodes");
    return r;
}

}  // namespace

TEST_CASE("lab07: a fragment exactly on a node gets the node's value exactly, and one ulp beside it stays finite", "[lab][lab07]") {
    for (NodeSet set : {NodeSet::GaussLobattoLegendre, NodeSet::Equispaced})
        for (int degree : {1, 2, 4, 8, 16}) {
            INFO(name_of(set) << " degree " << degree);
            const NodeProbe r = probe_at_nodes(set, degree);
            const int n = degree + 1;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const float* px = r.image.at(i, degree + 1 - j);  // GL row j is image row (height - 1 - j)
                    REQUIRE(std::isfinite(px[0]));
                    CHECK(px[0] == r.values[static_cast<std::size_t>(j * n + i)]);
                }
            for (int i = 0; i < n; ++i) {
                const float* px = r.image.at(i, 0);  // the top row: one ulp beside node i
                REQUIRE(std::isfinite(px[0]));
                const double reference = evaluate_element(r.values, r.nodes, r.weights, 0, px[1], px[2]);
                CHECK(std::abs(px[0] - reference) < (set == NodeSet::Equispaced && degree == 16 ? 1e-2 : 1e-5));
            }
        }
}

TEST_CASE("lab07: the sweep finds Runge's blow-up on equispaced nodes and float32's floor on GLL nodes", "[lab][lab07]") {
    test::TempDir dir;
    const auto run = test::run_lab("lab07_solution", {"sweep", "--size", "128x128", "--frames", "1", "--warmup", "0", "--set", "mesh=grid",
                                                      "--set", "columns=1", "--set", "rows=1", "--set", "field=runge", "--out-dir",
                                                      dir.path("sweep").string()},
                                   dir.path());
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    std::stringstream csv(test::read_text(dir.path("sweep") / "lab07-sweep.csv"));
    std::string header, line;
    std::getline(csv, header);
    std::map<std::string, std::string> rows;
    while (std::getline(csv, line)) {
        std::stringstream s(line);
        std::string set, degree;
        std::getline(s, set, ',');
        std::getline(s, degree, ',');
        rows[set + degree] = line;
    }
    REQUIRE(rows.count("gll16"));
    REQUIRE(rows.count("equispaced16"));
    CHECK(test::csv_value(header, rows["equispaced16"], "err_max") > 50.0);
    CHECK(test::csv_value(header, rows["gll16"], "err_max") < 0.1);
    CHECK(test::csv_value(header, rows["gll16"], "err_max") < test::csv_value(header, rows["gll4"], "err_max"));
    // float32 against double: the GLL floor stays near float's epsilon; equispaced weights amplify it.
    CHECK(test::csv_value(header, rows["gll16"], "float_err_max") < 1e-5);
    CHECK(test::csv_value(header, rows["equispaced16"], "float_err_max") > 10 * test::csv_value(header, rows["gll16"], "float_err_max"));
    // Memory: the basis grows with the degree only.
    CHECK(test::csv_value(header, rows["gll16"], "basis_bytes") == 17 * 8);
}

TEST_CASE("lab07: a degree-3 polynomial on degree-3 elements is drawn to float rounding, and the basis does not grow with elements", "[lab][lab07]") {
    test::TempDir dir;
    const auto run = test::run_lab("lab07_solution", {"sweep", "--size", "96x96", "--frames", "1", "--warmup", "0", "--set", "mesh=grid",
                                                      "--set", "field=polynomial", "--set", "degree=3", "--knob", "columns",
                                                      "--values", "1,8,64", "--set", "node_set=gll", "--out-dir", dir.path("sweep").string()},
                                   dir.path());
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    std::stringstream csv(test::read_text(dir.path("sweep") / "lab07-sweep.csv"));
    std::string header, one, eight, many;
    std::getline(csv, header);
    std::getline(csv, one);
    std::getline(csv, eight);
    std::getline(csv, many);
    for (const auto* row : {&one, &eight, &many}) {
        CHECK(test::csv_value(header, *row, "err_max") < 1e-5);
        CHECK(test::csv_value(header, *row, "basis_bytes") == 4 * 8);
    }
    CHECK(test::csv_value(header, many, "value_bytes") == 64.0 * test::csv_value(header, one, "value_bytes"));
}

TEST_CASE("lab07: the starter draws magenta until the colour map is written, and bad settings are one line", "[lab][lab07]") {
    test::TempDir dir;
    const auto starter = test::render("lab07", {}, dir.path(), "starter");
    INFO(starter.process.output);
    REQUIRE(starter.exit_code() == 0);
    CHECK(test::not_done_pixels(read_png(starter.png)) > 128 * 128 / 4);
    for (const auto& [setting, says] : std::vector<std::pair<std::string, std::string>>{
             {"degree=17", "degree"}, {"node_set=chebyshev", "chebyshev"}, {"columns=0", "columns"}}) {
        const auto run = test::render("lab07_solution", {setting}, dir.path(), "bad");
        INFO(run.process.output);
        CHECK(run.exit_code() != 0);
        CHECK(run.process.output.find(says) != std::string::npos);
        CHECK_FALSE(fs::exists(run.png));
    }
}
