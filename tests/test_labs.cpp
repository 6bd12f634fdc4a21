// Every lab binary, run as students, lecturers, CI and the grader run it.
#include "catch.hpp"
#include "test_support.h"

#include "common/params/case_file.h"
#include "common/app/sweep_report.h"
#include "gl_fixture.h"
#include "grader_fixture.h"
#include "lab_runner.h"
#include "per_lab.h"

#include "common/image/image_compare.h"
#include "grader/src/cases/cases.h"
#include "grader/src/grade/grade.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

// Labs whose every TODO runs on macOS's OpenGL 4.1 core profile: every lab whose lab.json asks for no more (lab 05's
// dispatch needs 4.3; the lab itself at 4.1 is the gl41 kind's, tests/test_gl41.cpp).
using test::labs_on_gl41;

// The public case file is the one declaration of a lab's named cases: `list` shows every one, and each renders
// by name in the solution and in the starter (which draws its "not done" colour, but must know the case).
void every_case_renders_by_name(const std::string& lab) {
    INFO(lab);
    const std::vector<RenderCase> cases = read_case_file(test::source_root() / "grader" / "cases" / (lab + ".json"), lab);
    REQUIRE(cases.size() >= static_cast<std::size_t>(test::lab_rule("public_cases")));
    const auto dir = test::temp_dir("cases-" + lab);
    const test::LabRun list = test::run_lab(lab + "_solution", {"list"}, dir);
    REQUIRE(list.exit_code() == 0);
    for (const auto& c : cases) {
        INFO(c.name);
        CHECK(list.process.output.find("  " + c.name + " ") != std::string::npos);
        for (const std::string& binary : {lab + "_solution", lab}) {
            const test::LabRun run = test::run_lab(binary, {"render", "--case", c.name, "--size", "24x24", "--frames", "1",
                                                            "--warmup", "0", "--out", (dir / (c.name + ".png")).string()},
                                                   dir);
            INFO(binary << ": " << run.process.output);
            CHECK(run.exit_code() == 0);
        }
    }
}

Image must_render(const test::LabRun& run) {
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    return read_png(run.png);
}


// A copy of the files lab01_solution loads, to break on purpose (GSV_ROOT points the binary at it).
fs::path copy_of_lab01(const std::string& name) {
    const fs::path root = test::temp_dir(name);
    test::copy_lab_kit(test::source_root(), root, "lab01_gooch");
    fs::copy(test::source_root() / "data" / "meshes", root / "data" / "meshes", fs::copy_options::recursive);
    return root;
}

int line_of(const fs::path& file, const std::string& needle) {
    std::ifstream in(file);
    int n = 0;
    for (std::string line; std::getline(in, line);) {
        ++n;
        if (line.find(needle) != std::string::npos) return n;
    }
    return -1;
}

}  // namespace

TEST_CASE("labs: every case and demo of each public case file renders by name, starter and solution", "[lab][labs]") {
    for (const auto& lab : labs_on_gl41()) every_case_renders_by_name(lab);
}

// A lab that needs OpenGL 4.3 alone, with the label gl43 (left out on macOS).
GSV_PER_LAB_TEST("every case and demo of its public case file renders by name, starter and solution", "[lab][labs]",
                 every_case_renders_by_name, test::PerLab::NeedsGl43)

TEST_CASE("labs: a case file's mistake is named where it is written, and without the file --set still works", "[lab][labs]") {
    const fs::path root = copy_of_lab01("case-file");
    fs::create_directories(root / "grader" / "cases");
    const std::string original = test::read_text(test::source_root() / "grader" / "cases" / "lab01.json");
    const auto write_cases = [&](const std::string& from, const std::string& to) {
        std::string text = original;
        REQUIRE(text.find(from) != std::string::npos);
        text.replace(text.find(from), from.size(), to);
        std::ofstream(root / "grader" / "cases" / "lab01.json") << text;
        return line_of(root / "grader" / "cases" / "lab01.json", to);
    };
    const std::vector<std::string> env{"GSV_ROOT=" + root.string()};
    const auto dir = test::temp_dir("case-file-out");
    const int line = write_cases("\"mesh_resolution=8\"", "\"mesh_resolutoin=8\"");
    for (const std::vector<std::string>& args : {std::vector<std::string>{"list"},
                                               std::vector<std::string>{"render", "--case", "gooch", "--out", "x.png"}}) {
        const test::LabRun run = test::run_lab("lab01_solution", args, dir, env);
        INFO(run.process.output);
        CHECK(run.exit_code() != 0);
        CHECK(run.process.output.find("lab01.json:" + std::to_string(line) + ":") != std::string::npos);
        CHECK(run.process.output.find("unknown parameter 'mesh_resolutoin'") != std::string::npos);
    }
    write_cases("\"mesh_resolution=8\"", "\"mesh_resolution=99999\"");
    const test::LabRun range = test::run_lab("lab01_solution", {"list"}, dir, env);
    CHECK(range.exit_code() != 0);
    CHECK(range.process.output.find("99999") != std::string::npos);
    // Without its case file a lab still renders what --set asks for, as the grader runs it; --case names the file.
    fs::remove(root / "grader" / "cases" / "lab01.json");
    CHECK(test::render("lab01_solution", {"shading=phong"}, dir, "no-case-file", {}, env).exit_code() == 0);
    const test::LabRun missing = test::run_lab("lab01_solution", {"render", "--case", "gooch", "--out", "y.png"}, dir, env);
    CHECK(missing.exit_code() != 0);
    CHECK(missing.process.output.find("cannot find the case file") != std::string::npos);
    CHECK(missing.process.output.find("lab01.json") != std::string::npos);
}

TEST_CASE("labs: every lab but 05 runs on an OpenGL 4.1 core context and renders the same image", "[lab][labs]") {
    const auto dir = test::temp_dir("gl41");
    for (const auto& lab : labs_on_gl41()) {
        INFO(lab);
        // The override makes Mesa report 4.1, so glad loads no 4.2+ entry point: a call to one would crash.
        const Image at41 = must_render(test::render(lab + "_solution", {}, dir, lab + "-41", {"--gl", "4.1"},
                                                    {"MESA_GL_VERSION_OVERRIDE=4.1", "MESA_GLSL_VERSION_OVERRIDE=410"}));
        const Json report = read_json_file(dir / (lab + "-41.json"));
        CHECK(report.object_at("gl").string_at("effective") == "4.1");
        CHECK(report.object_at("gl").string_at("version").rfind("4.1", 0) == 0);
        const Image at45 = must_render(test::render(lab + "_solution", {}, dir, lab + "-45", {"--gl", "4.5"}));
        CHECK(compare_images(at41, at45, {}).max_channel_diff == 0);
    }
}

TEST_CASE("labs: a context below what the lab needs stops with one clear line and status 3", "[lab][labs]") {
    // Mesa's MESA_GL_VERSION_OVERRIDE makes the old context; another driver ignores it.
    {
        const auto context = test::headless_context();
        const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
        if (!version || std::string(version).find("Mesa") == std::string::npos) {
            WARN("not Mesa (" << (version ? version : "no version") << "): no way to ask for an older context here");
            return;
        }
    }
    const auto dir = test::temp_dir("gl33");
    const auto run = test::render("lab01_solution", {}, dir, "old", {}, {"MESA_GL_VERSION_OVERRIDE=3.3"});
    INFO(run.process.output);
    CHECK(run.exit_code() == 3);
    CHECK(run.process.output.find("needs OpenGL 4.1") != std::string::npos);
    CHECK_FALSE(fs::exists(run.png));
}

TEST_CASE("lab01: core and compat profiles, EGL and OSMesa backends give the same image", "[lab][labs]") {
    const auto dir = test::temp_dir("profiles");
    for (const char* name : {"gooch", "phong", "silhouette", "back-faces", "per-vertex"}) {
        INFO(name);
        const Image core = must_render(test::render("lab01_solution", {}, dir, std::string(name) + "-core", {"--case", name}));
        const Image compat = must_render(test::render("lab01_solution", {}, dir, std::string(name) + "-compat",
                                                      {"--case", name, "--profile", "compat"}));
        CHECK(compare_images(compat, core, {}).max_channel_diff == 0);
        CHECK(read_json_file(dir / (std::string(name) + "-compat.json")).object_at("gl").string_at("profile") == "compat");
#if GSV_HAVE_OSMESA
        const Image osmesa = must_render(test::render("lab01_solution", {}, dir, std::string(name) + "-osmesa",
                                                      {"--case", name, "--backend", "osmesa"}));
        CHECK(compare_images(osmesa, core, {}).max_channel_diff == 0);
        CHECK(read_json_file(dir / (std::string(name) + "-osmesa.json")).object_at("gl").string_at("backend") == "osmesa");
#endif
    }
}

namespace {

GradeOptions grading_options(const std::string& lab) {
    GradeOptions options;
    options.diagnose = DiagnoseCases::Off;  // the diagnosis has tests of its own (test_grader_diagnosis*.cpp)
    options.kit_root = test::source_root();
    options.bin_dir = test::bin_dir();
    options.labs = {lab};
    options.allow_readable_kit = true;  // grading, not the walls, is tested here
    return options;
}

// The solution scores full marks against the goldens and live (hidden cases included), and the shipped starter fails
// every TODO. Timing is graded apart (below), alone: here the labs run beside other tests.
void solution_full_marks_starter_zero(const std::string& lab) {
    GradeOptions options = grading_options(lab);
    options.timing = false;
    options.seed = 11;
    // The live solution run and the starter's share their references: one render of each case.
    options.reference_cache = std::make_shared<ReferenceCache>();
    for (bool self_check : {true, false}) {
        options.submission = test::solution_submission(lab, "grade-solution-submission-" + lab);
        options.self_check = self_check;
        // Relative, as `scripts/kit grade` passes it: the lab processes run in per-case folders.
        const fs::path out = test::temp_dir(self_check ? "grade-golden-" + lab : "grade-live-" + lab);
        fs::current_path(out.parent_path());
        options.out_dir = out.filename();
        const GradeReport report = grade(options);
        CHECK(report.mode == (self_check ? "self-check" : "instructor"));
        CHECK(report.hidden_included == !self_check);
        REQUIRE(report.results.size() >= static_cast<std::size_t>(test::lab_rule("public_cases")));
        for (const auto& r : report.results) {
            INFO(r.name << " " << r.kind << ": " << status_name(r.status) << " " << r.detail << "\n" << r.output);
            CHECK(r.status == CaseStatus::Passed);
            CHECK(r.reference == (self_check ? "golden" : "live"));
        }
        CHECK(report.score() == report.max_score());
    }
    // The shipped starter: it builds and runs, and every TODO's check fails.
    options.submission.clear();
    options.self_check = false;
    options.out_dir = test::temp_dir("grade-starter-" + lab);
    std::set<std::string> todos_failed, todos;
    for (const auto& r : grade(options).results) {
        INFO(r.name << ": " << status_name(r.status) << " " << r.detail);
        // It ran and rendered, and says why it lost the points: not done, another TODO first, or a wrong image.
        CHECK((r.status == CaseStatus::NotDone || r.status == CaseStatus::NeedsFirst || r.status == CaseStatus::WrongImage ||
               r.status == CaseStatus::BlankImage || r.status == CaseStatus::WrongData));
        todos.insert(r.todo);
        if (r.points == 0) todos_failed.insert(r.todo);
    }
    CHECK(todos_failed == todos);
}

}  // namespace

constexpr const char* kFullMarksTest =
    "the solution scores full marks against the goldens and live, and the starter fails every TODO";
GSV_PER_LAB_TEST(kFullMarksTest, "[lab][labs]", solution_full_marks_starter_zero, test::PerLab::OnGl41)

TEST_CASE("every lab on OpenGL 4.1 has its full-marks test above", "[lab][labs]") {
    CHECK_FALSE(labs_on_gl41().empty());
    CHECK(test::labs_missing_test(kFullMarksTest, test::PerLab::OnGl41).empty());
}

// Tagged [timing] (ctest runs it alone): live grading times the solution against itself, which noise must not fail.
// Only the timed cases: the rest of live grading is the test above, run beside other tests.
TEST_CASE("every lab: the solution's timed cases pass their timing against itself", "[lab][labs][timing]") {
  for (const std::string& lab : labs_on_gl41()) {
    INFO(lab);
    GradeOptions options = grading_options(lab);
    options.submission = test::solution_submission(lab, "grade-timing-submission-" + lab);
    options.hidden = false;
    for (const GradeCase& c : load_lab_cases(test::source_root() / "grader" / "cases" / (lab + ".json")).cases)
        if (c.timing.points > 0) options.cases.push_back(c.name);
    REQUIRE_FALSE(options.cases.empty());
    options.out_dir = test::temp_dir("grade-timing-" + lab);
    const GradeReport report = grade(options);
    CHECK(report.timing_included);
    int timed = 0;
    for (const auto& r : report.results) {
        INFO(r.name << " " << r.kind << ": " << status_name(r.status) << " " << r.detail << "\n" << r.output);
        CHECK(r.status == CaseStatus::Passed);
        timed += r.kind == "timing";
    }
    CHECK(timed == static_cast<int>(options.cases.size()));
  }
}

TEST_CASE("lab01: the starter renders a clear 'not done' image: magenta where the shading is missing", "[lab][labs]") {
    const auto dir = test::temp_dir("starter");
    const Image image = must_render(test::render("lab01", {}, dir, "starter"));
    CHECK(test::not_done_pixels(image) > image.width * image.height / 5);
}

TEST_CASE("lab01: bad command lines give one line naming the culprit and status 2", "[lab][labs]") {
    const auto dir = test::temp_dir("bad-cli");
    struct Bad {
        std::vector<std::string> args;
        std::string says;
    };
    const std::vector<Bad> bad = {
        {{"render", "--bogus"}, "unknown option '--bogus'"},
        {{"render", "--set", "alpha=1.5"}, "parameter 'alpha' = 1.5 is out of range [0, 1]"},
        {{"render", "--set", "mesh_resolution=2"}, "parameter 'mesh_resolution' = 2 is out of range [3, 1024]"},
        {{"render", "--set", "shading=toon"}, "parameter 'shading' = 'toon' is not one of: phong, gooch"},
        {{"render", "--set", "glossiness=3"}, "unknown parameter 'glossiness'"},
        {{"render", "--set", "scale=1,2"}, "needs three comma-separated numbers"},
        {{"render", "--case", "nope"}, "unknown case 'nope'"},
        {{"render", "--size", "0x10"}, "--size = 0 is out of range"},
        {{"render", "--profile", "metal"}, "unknown profile 'metal'"},
        {{"render", "--profile", "es", "--gl", "4.1"}, "GL version '4.1' is out of range [3.0, 3.2] for the es profile"},
        {{"render", "--gl", "3.0"}, "(OpenGL ES versions go with --profile es)"},
        {{"paint"}, "unknown mode 'paint'"},
    };
    for (const auto& b : bad) {
        const auto run = test::run_lab("lab01_solution", b.args, dir);
        INFO(run.process.output);
        CHECK(run.exit_code() == 2);
        const auto lines = test::lines_of(run.process.output);
        REQUIRE(lines.size() == 1);
        CHECK(lines[0].find(b.says) != std::string::npos);
    }
    CHECK(fs::is_empty(dir));  // nothing written
}

TEST_CASE("lab01: a missing shader, a compile error, a missing or corrupt mesh: clear error, status 1", "[lab][labs]") {
    {
        const auto root = copy_of_lab01("missing-shader");
        fs::remove(root / "solutions" / "lab01_gooch" / "shade.frag");
        const auto run = test::render("lab01_solution", {}, root, "x", {}, {"GSV_ROOT=" + root.string()});
        INFO(run.process.output);
        CHECK(run.exit_code() == 1);
        CHECK(run.process.output.find("shade.frag") != std::string::npos);
        CHECK_FALSE(fs::exists(run.png));
    }
    {
        const auto root = copy_of_lab01("compile-error");
        const fs::path phong = root / "solutions" / "lab01_gooch" / "phong.glsl";
        test::replace_in_file(phong, "vec3 r = reflect(-l, n);", "vec3 r = reflect(-l, n) +;");
        const int line = line_of(phong, "vec3 r = reflect(-l, n) +;");
        const auto run = test::render("lab01_solution", {}, root, "x", {}, {"GSV_ROOT=" + root.string()});
        INFO(run.process.output);
        CHECK(run.exit_code() == 1);
        CHECK(run.process.output.find("shader compile error") != std::string::npos);
        CHECK(run.process.output.find("phong.glsl:" + std::to_string(line) + ":") != std::string::npos);
        CHECK(run.process.output.find("vec3 r = reflect(-l, n) +;") != std::string::npos);  // the source line
    }
    {
        const auto root = copy_of_lab01("missing-mesh");
        fs::remove(root / "data" / "meshes" / "teapot.obj");
        const auto run = test::render("lab01_solution", {}, root, "x", {}, {"GSV_ROOT=" + root.string()});
        INFO(run.process.output);
        CHECK(run.exit_code() == 1);
        CHECK(run.process.output.find("teapot.obj") != std::string::npos);
    }
    {
        const auto root = copy_of_lab01("corrupt-mesh");
        std::ofstream(root / "data" / "meshes" / "teapot.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n";
        const auto run = test::render("lab01_solution", {}, root, "x", {}, {"GSV_ROOT=" + root.string()});
        INFO(run.process.output);
        CHECK(run.exit_code() == 1);
        CHECK(run.process.output.find("teapot.obj:3") != std::string::npos);
    }
}

TEST_CASE("lab01: assets are found from any working directory, never through it", "[lab][labs]") {
    const auto elsewhere = test::temp_dir("cwd");
    const auto run = test::render("lab01_solution", {"model=teapot"}, elsewhere, "teapot");
    INFO(run.process.output);
    CHECK(run.exit_code() == 0);
}

TEST_CASE("lab01: sweep mode measures both shading rates against the exact sphere, as a table, CSV and plots", "[lab][labs]") {
    const auto dir = test::temp_dir("sweep");
    const auto run = test::run_lab("lab01_solution",
                                   {"sweep", "--size", "128x128", "--frames", "1", "--warmup", "0", "--out-dir", dir.string()},
                                   dir);
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    const std::string csv = test::read_text(dir / "lab01-sweep.csv");
    const auto rows = test::lines_of(csv);
    REQUIRE(rows.size() == 1 + 2 * 10);  // header, 2 shading rates x 10 resolutions
    const std::string& header = rows[0];
    CHECK(header == "shading_rate,mesh_resolution,median_ms,min_ms,rmse,max_diff,shading_err_mean,shading_err_max,"
                    "normal_err_mean_deg,normal_err_max_deg,work,bound_ms,fraction,limiter,p25_ms,p75_ms,reference");
    // The reference is named in words: the exact sphere, not the finest mesh.
    CHECK(rows[1].find(",the exact sphere, ray-cast") == std::string::npos);  // commas in a cell would split it
    CHECK(rows[1].find("the exact sphere; ray-cast at each pixel and lit with its exact normal") != std::string::npos);
    auto value = [&](int row, const std::string& name) { return test::csv_value(header, rows[row], name); };
    REQUIRE(rows[1].rfind("vertex,6,", 0) == 0);
    REQUIRE(rows[8].rfind("vertex,128,", 0) == 0);
    REQUIRE(rows[11].rfind("fragment,6,", 0) == 0);
    REQUIRE(rows[18].rfind("fragment,128,", 0) == 0);
    REQUIRE(rows[20].rfind("fragment,512,", 0) == 0);
    // Against the exact sphere, the image error falls as the mesh is refined, to far below one level...
    CHECK(value(20, "rmse") < 0.25 * value(11, "rmse"));
    CHECK(value(20, "rmse") < 0.2);
    CHECK(value(10, "rmse") < 0.2);
    // ...and so does the normal per fragment lights with (about 360/6/2 degrees at 6 segments).
    CHECK(value(11, "normal_err_mean_deg") > 5.0);
    CHECK(value(20, "normal_err_mean_deg") < 0.5);
    // Per vertex lights with no interpolated normal: no normal error is claimed for it.
    CHECK(test::count_of(rows[1], ",,") >= 1);
    CHECK_THROWS(value(1, "normal_err_mean_deg"));
    // Where the outline has converged (128 segments), what per vertex lights with still errs about twice as much
    // as per fragment (0.056 and 0.026 levels measured).
    CHECK(value(8, "shading_err_mean") > 1.5 * value(18, "shading_err_mean"));
    CHECK(fs::exists(dir / "lab01-sweep.gp"));
    CHECK(fs::exists(dir / "lab01-tradeoff.gp"));
    // The same rows as a Markdown table for the slides: a header, a separator and one line per row.
    const std::string md = test::read_text(dir / "lab01-sweep.md");
    CHECK(md.rfind("| shading_rate | mesh_resolution | ms/frame (spread) | RMSE | max diff |", 0) == 0);
    CHECK(md.find("\n| fragment | 512 | ") != std::string::npos);
    CHECK(test::count_of(md, "\n| ") == 1 + 20);  // the separator, then 2 shading rates x 10 resolutions
    if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
        CHECK(fs::file_size(dir / "lab01-sweep.png") > 1000);
        CHECK(fs::file_size(dir / "lab01-tradeoff.png") > 1000);
    }
}

TEST_CASE("sweep report: a measure only some rows have gets one column, blank or '-' where a row lacks it, and a summary line", "[lab][labs]") {
    SweepReport report;
    report.lab = "labX";
    report.knob = "k";
    report.series = "mode";
    report.reference_name = "the exact answer, analytic";
    report.rows = {{"a", "1", 2.0, 2.0, 1.5, 2.5, 0.5, 3, {{"shared", 1.0}}, "", std::nullopt},
                   {"b", "1", 4.0, 4.0, 3.5, 4.5, 0.25, 2, {{"only_b", 7.0}, {"shared", 2.0}}, "", std::nullopt}};
    const auto csv = test::lines_of(report.csv());
    REQUIRE(csv.size() == 3);
    // The spread and the reference in words come last, so a column's number does not depend on them.
    CHECK(csv[0] == "mode,k,median_ms,min_ms,rmse,max_diff,shared,only_b,p25_ms,p75_ms,reference");
    CHECK(csv[1] == "a,1,2.0000,2.0000,0.5000,3,1,,1.5000,2.5000,the exact answer; analytic");
    CHECK(csv[2] == "b,1,4.0000,4.0000,0.2500,2,2,7,3.5000,4.5000,the exact answer; analytic");
    const std::string md = report.markdown();
    CHECK(md.find("| mode | k | ms/frame (spread) | RMSE | max diff | shared | only_b |") == 0);
    CHECK(md.find("| a | 1 | 2 (1.5-2.5) | 0.5 | 3 | 1 | - |") != std::string::npos);
    CHECK(md.find("| b | 1 | 4 (3.5-4.5) | 0.25 | 2 | 2 | 7 |") != std::string::npos);
    CHECK(md.find("error against the exact answer, analytic") != std::string::npos);
    const std::string table = report.table();
    CHECK(table.find("only_b") != std::string::npos);
    CHECK(table.find("error against the exact answer, analytic") != std::string::npos);
    // What accuracy costs, in a line: the cheapest setting, the most accurate, and the ratios between them.
    const auto summary = test::lines_of(report.summary());
    REQUIRE(summary.size() == 2);
    CHECK(summary[0] == "lab,knob,error,cheapest,cheapest_error,cheapest_ms,most_accurate,accurate_error,accurate_ms,time_ratio,error_ratio,"
                        "cheapest_fraction,cheapest_limiter,accurate_fraction,accurate_limiter");
    // No ceilings measured: no share of a bound, and no limiter.
    CHECK(summary[1] == "labX,k,rmse,mode=a k=1,0.5,2,mode=b k=1,0.25,4,2,2,,,,");
    // A plotted measure of the lab's own replaces the RMSE; a row without it is neither.
    report.plotted_error = "only_b";
    CHECK(test::lines_of(report.summary())[1] == "labX,k,only_b,mode=a k=1,-,2,mode=b k=1,7,4,2,-,,,,");
}

TEST_CASE("sweep report: with this device's ceilings, each end's share of the bound and its limiter, <= for an upper bound, and the bound in the time plot", "[unit]") {
    SweepReport report;
    report.lab = "labX";
    report.knob = "k";
    report.reference_name = "k=4";
    Roofline fetches;  // the most the frame can do: rays that end early do less
    fetches.bound_ms = 1.0;
    fetches.limiter = "texture (fragment)";
    fetches.upper_bound = true;
    Roofline storage;
    storage.bound_ms = 3.0;
    storage.limiter = "storage compute";
    report.rows = {{"", "1", 2.0, 2.0, 1.5, 2.5, 0.5, 3, {}, "<= 1M fetch RG32F 2D fragment", fetches},
                   {"", "2", 4.0, 4.0, 3.5, 4.5, 0.25, 2, {}, "96M storage compute", storage},
                   {"", "3", 8.0, 8.0, 7.5, 8.5, 0.125, 1, {}, "", std::nullopt}};
    const auto summary = test::lines_of(report.summary());
    REQUIRE(summary.size() == 2);
    // The cheapest (k=1) reaches at most 1/2 of its bound; the most accurate (k=3) states no work.
    CHECK(summary[1] == "labX,k,rmse,k=1,0.5,2,k=3,0.125,8,4,4,<=0.5,texture (fragment),,");
    report.rows.pop_back();  // now k=2 is the most accurate: 3 ms of 4
    CHECK(test::lines_of(report.summary())[1] == "labX,k,rmse,k=1,0.5,2,k=2,0.25,4,2,2,<=0.5,texture (fragment),0.75,storage compute");
    // The table and the Markdown mark the upper bound the same way.
    CHECK(report.table().find("<=50.0%") != std::string::npos);
    const std::string md = report.markdown();
    CHECK(md.rfind("| k | ms/frame (spread) | RMSE | max diff | ceiling |", 0) == 0);
    CHECK(md.find("| 1 | 2 (1.5-2.5) | 0.5 | 3 | <=50% |") != std::string::npos);
    CHECK(md.find("| 2 | 4 (3.5-4.5) | 0.25 | 2 | 75% |") != std::string::npos);

    // The time panel: the bound (the CSV's 8th column, bound_ms) dashed beside the times, keyed with its limiters.
    test::TempDir dir;
    report.write(dir.path());
    const std::string gp = test::read_text(dir.path() / "labX-sweep.gp");
    const std::string csv_head = test::lines_of(test::read_text(dir.path() / "labX-sweep.csv"))[0];
    CHECK(csv_head.rfind("series,k,median_ms,min_ms,rmse,max_diff,work,bound_ms,", 0) == 0);
    CHECK(gp.find("using 2:(strcol(1) eq '-' ? $8 : 1/0) with linespoints lw 3 dt 2") != std::string::npos);
    CHECK(gp.find("title \"the fastest this device allows\\n(texture (fragment), storage compute)\"") != std::string::npos);
    CHECK(gp.find("set offsets 0, 0, graph 0.3, 0") != std::string::npos);
    // Without ceilings, no bound is drawn.
    for (auto& row : report.rows) row.roofline.reset();
    test::TempDir plain;
    report.write(plain.path());
    const std::string plain_gp = test::read_text(plain.path() / "labX-sweep.gp");
    CHECK(plain_gp.find("dt 2") == std::string::npos);
    CHECK(plain_gp.find("the fastest this device allows") == std::string::npos);
    CHECK(test::lines_of(report.summary())[1] == "labX,k,rmse,k=1,0.5,2,k=2,0.25,4,2,2,,,,");
}

TEST_CASE("sweep report: a time or ratio with its spread is one cell in the table and the Markdown, three in the CSV", "[lab][labs]") {
    SweepReport report;
    report.lab = "labX";
    report.knob = "k";
    report.reference_name = "k=2";
    SweepRow row;
    row.knob = "1";
    row.extra = {{"uber_over_specialised", 2.5}, {"uber_over_specialised_lo", 2.25}, {"uber_over_specialised_hi", 2.75}, {"x_lo", 1}};
    report.rows = {row};
    const std::string md = report.markdown();
    CHECK(md.find("| k | ms/frame (spread) | RMSE | max diff | uber_over_specialised | x_lo |") == 0);
    CHECK(md.find("| 2.5 (2.25-2.75) | 1 |") != std::string::npos);
    CHECK(report.table().find("2.5 (2.25-2.75)") != std::string::npos);
    CHECK(test::lines_of(report.csv())[0] ==
          "series,k,median_ms,min_ms,rmse,max_diff,uber_over_specialised,uber_over_specialised_lo,uber_over_specialised_hi,x_lo,"
          "p25_ms,p75_ms,reference");
}
