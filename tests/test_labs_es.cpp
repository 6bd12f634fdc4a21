// Every lab on OpenGL ES (--profile es), at the lowest ES version it declares, against the same labs on the desktop
// core profile: the same shader files, graded the same way.
#include "catch.hpp"
#include "test_support.h"

#include "gl_fixture.h"
#include "grader_fixture.h"
#include "lab_runner.h"
#include "per_lab.h"

#include "common/image/image_compare.h"
#include "grader/src/grade/grade.h"

#include <map>
#include <set>
#include <sstream>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

using test::all_labs;

// The lowest ES version each lab declares (LabInfo::needs_es): the WebGL 2 feature set, lab 05 too (transform feedback
// steps its particles there; its cases of compute's own TODO, L05-T2, say "feature": "compute", which lifts them to 3.1).
std::string declared_es_version(const std::string&) { return "3.0"; }

Image must_render(const test::LabRun& run) {
    INFO(run.process.output);
    REQUIRE(run.exit_code() == 0);
    return read_png(run.png);
}

}  // namespace

// The measured difference between the profiles on llvmpipe is zero for every public case of every lab (94 cases,
// lab 05's particle arrays too), so the comparison here has no tolerance: a pixel that moves is a real difference
// between the profiles, to be understood before any tolerance is written down for it.
namespace {

// Graded on ES against the goldens, full marks; then the same build on the core profile, image for image.
void es_full_marks_and_core_images(const std::string& lab) {
    const auto submission = test::solution_submission(lab, "es-solution-submission-" + lab);
    GradeOptions options;
    options.diagnose = DiagnoseCases::Off;  // the diagnosis has tests of its own (test_grader_diagnosis*.cpp)
    options.kit_root = test::source_root();
    options.bin_dir = test::bin_dir();
    options.labs = {lab};
    options.self_check = true;  // against the goldens: core-profile images
    options.submission = submission;
    options.profile = Profile::Es;
    options.out_dir = test::temp_dir("es-grade-es-" + lab);
    const GradeReport es = grade(options);
    CHECK(es.profile == "es");
    CHECK(es.mode == "self-check");
    REQUIRE(es.results.size() >= static_cast<std::size_t>(test::lab_rule("public_cases")));
    for (const auto& r : es.results) {
        INFO(r.lab << "/" << r.name << ": " << status_name(r.status) << " " << r.detail << "\n" << r.output);
        CHECK(r.status == CaseStatus::Passed);
        CHECK(r.output.find("es profile") != std::string::npos);
        CHECK(r.reproduce.find(" --profile es") != std::string::npos);
        // Lab 05's particles are matched within two pixels against the goldens, and the detail says so.
        if (lab == "lab05") CHECK(r.detail.find("matched within 2 px") != std::string::npos);
    }
    CHECK(es.score() == es.max_score());

    // The same build graded on the core profile: each case's image compared with the ES one, pixel for pixel.
    GradeOptions core_options = options;
    core_options.submission.clear();
    core_options.student_bin_dir = options.out_dir / "submission-build" / "build" / "bin";
    core_options.student_root = options.out_dir / "submission-build" / "kit";
    core_options.profile = Profile::Core;
    core_options.out_dir = test::temp_dir("es-grade-core-" + lab);
    const GradeReport core = grade(core_options);
    REQUIRE(core.results.size() == es.results.size());
    for (std::size_t i = 0; i < es.results.size(); ++i) {
        const CaseResult& a = es.results[i];
        const CaseResult& b = core.results[i];
        INFO(a.lab << "/" << a.name);
        REQUIRE(a.name == b.name);
        CHECK(b.status == CaseStatus::Passed);
        if (a.kind != "image" || a.actual_png.empty()) continue;
        const Image on_es = read_png(options.out_dir / a.actual_png);
        const Image on_core = read_png(core_options.out_dir / b.actual_png);
        const ImageDiff diff = compare_images(on_es, on_core, {});
        CHECK(diff.max_channel_diff == 0);
        CHECK(diff.differing_pixels == 0);
    }
}

}  // namespace

// Every lab, lab 05 too (its ES 3.0 path needs no 4.3): no gl43 label.
constexpr const char* kEsFullMarksTest =
    "es: {lab} graded on its lowest OpenGL ES version: the solution full marks, every image the core profile's";
GSV_PER_LAB_TEST(kEsFullMarksTest, "[lab][es]", es_full_marks_and_core_images, test::PerLab::Every, test::Gl43Tag::Never)

TEST_CASE("es: every lab has its full-marks test above", "[lab][es]") {
    CHECK_FALSE(all_labs().empty());
    CHECK(test::labs_missing_test(kEsFullMarksTest, test::PerLab::Every).empty());
}

TEST_CASE("es: graded on OpenGL ES, the starter fails every TODO while the reference renders every case", "[lab][es]") {
    GradeOptions options;
    options.diagnose = DiagnoseCases::Off;  // the diagnosis has tests of its own (test_grader_diagnosis*.cpp)
    options.kit_root = test::source_root();
    options.bin_dir = test::bin_dir();
    options.profile = Profile::Es;
    options.timing = false;
    options.seed = 11;  // hidden cases too: lab 03's separate textures run at the ES 3.2 their case asks for
    options.allow_readable_kit = true;  // grading, not the walls, is tested here
    options.out_dir = test::temp_dir("es-grade-starter");
    const GradeReport report = grade(options);
    CHECK(report.mode == "instructor");
    CHECK(report.hidden_included);
    std::map<std::string, std::set<std::string>> todos, todos_failed;
    bool separate_graded = false;
    for (const auto& r : report.results) {
        INFO(r.lab << "/" << r.name << ": " << status_name(r.status) << " " << r.detail << "\n" << r.output);
        // It ran and rendered on ES, and says why it lost the points; the live reference never failed.
        CHECK((r.status == CaseStatus::NotDone || r.status == CaseStatus::NeedsFirst || r.status == CaseStatus::WrongImage ||
               r.status == CaseStatus::BlankImage || r.status == CaseStatus::WrongData));
        CHECK(r.reference == "live");
        todos[r.lab].insert(r.todo);
        if (r.points == 0) todos_failed[r.lab].insert(r.todo);
        if (r.name.rfind("hidden-separate", 0) == 0) {
            separate_graded = true;
            CHECK(r.reproduce.find("--profile es --gl 3.2") != std::string::npos);
        }
    }
    CHECK(separate_graded);
    CHECK(todos.size() == all_labs().size());
    CHECK(todos_failed == todos);
}

TEST_CASE("es: each lab holds to its declared ES version, and what needs more is refused naming the version", "[lab][es]") {
    const auto dir = test::temp_dir("es-versions");
    for (const auto& lab : all_labs()) {
        INFO(lab);
        const test::LabRun run = test::render(lab + "_solution", {}, dir, lab, {"--profile", "es", "--size", "32x32"});
        must_render(run);
        const Json gl = read_json_file(run.json).object_at("gl");
        CHECK(gl.string_at("profile") == "es");
        CHECK(gl.string_at("effective") == declared_es_version(lab));
        CHECK(gl.string_at("version").rfind("OpenGL ES", 0) == 0);
    }
    struct Refused {
        std::string lab;
        std::vector<std::string> args;
        std::string says;
    };
    const std::vector<Refused> refused = {
        {"lab03", {"--case", "separate"},
         "storage=separate (slice k is read from uFlowSlices[k]) needs an array of samplers indexed by a uniform, which "
         "OpenGL ES has from 3.2; this run holds to 3.0 (--gl 3.2 where the driver offers it)"},
    };
    for (const auto& r : refused) {
        std::vector<std::string> args{"--profile", "es"};
        args.insert(args.end(), r.args.begin(), r.args.end());
        const test::LabRun run = test::render(r.lab + "_solution", {}, dir, r.lab + "-refused", args);
        INFO(run.process.output);
        CHECK(run.exit_code() == 3);
        CHECK(run.process.output.find(r.says) != std::string::npos);
        CHECK_FALSE(fs::exists(run.png));
    }
    // Where the driver has the version, asking for it runs the same case: the picture the core profile draws.
    for (const auto& [lab, name] : std::vector<std::pair<std::string, std::string>>{{"lab03", "separate"}, {"lab07", "annulus"}}) {
        INFO(lab << " " << name);
        const Image es32 = must_render(test::render(lab + "_solution", {}, dir, name + "-es32", {"--case", name, "--profile", "es", "--gl", "3.2"}));
        const Image core = must_render(test::render(lab + "_solution", {}, dir, name + "-core", {"--case", name}));
        CHECK(compare_images(es32, core, {}).max_channel_diff == 0);
    }
}

TEST_CASE("es: without float render targets or float filtering the kit says what is lost, and lab 06 reads depth through colour", "[lab][es]") {
    const auto dir = test::temp_dir("es-extensions");
    const Image core = must_render(test::render("lab01_solution", {}, dir, "core"));
    CHECK(read_json_file(dir / "core.json").bool_at("float_target"));
    // Mesa drops an extension from the list on request: a driver without GL_EXT_color_buffer_float, as on some phones.
    // Other drivers (a student's GPU) ignore the variable, and there is nothing to pretend with.
    const bool mesa = read_json_file(dir / "core.json").object_at("gl").string_at("version").find("Mesa") != std::string::npos;
    if (!mesa) {
        WARN("not Mesa: the missing-extension half is skipped (MESA_EXTENSION_OVERRIDE is Mesa's)");
    } else {
        const test::LabRun no_float = test::render("lab01_solution", {}, dir, "no-float", {"--profile", "es"},
                                                   {"MESA_EXTENSION_OVERRIDE=-GL_EXT_color_buffer_float"});
        const Image rgba8 = must_render(no_float);
        CHECK(test::count_of(no_float.process.output, "lacks GL_EXT_color_buffer_float: frames render into RGBA8, so NaN and Inf "
                                                      "pixels are not detected") == 1);
        CHECK_FALSE(read_json_file(no_float.json).bool_at("float_target"));
        CHECK(compare_images(rgba8, core, {}).max_channel_diff == 0);
        // A lab that filters a float texture cannot draw right without GL_OES_texture_float_linear: refused, not black.
        const test::LabRun no_linear = test::render("lab02_solution", {}, dir, "no-linear", {"--profile", "es"},
                                                    {"MESA_EXTENSION_OVERRIDE=-GL_OES_texture_float_linear"});
        INFO(no_linear.process.output);
        CHECK(no_linear.exit_code() == 3);
        CHECK(no_linear.process.output.find("linear filtering of a float texture on OpenGL ES needs "
                                            "GL_OES_texture_float_linear, which this driver lacks") != std::string::npos);
    }
    // Lab 06's debug images include each port's depth, which ES cannot read back directly.
    for (const std::string profile : {"core", "es"}) {
        const test::LabRun run = test::render("lab06_solution", {}, dir, "lab06-" + profile, {"--profile", profile, "--debug-images"});
        must_render(run);
    }
    int depth_images = 0;
    for (const auto& entry : fs::directory_iterator(dir / "lab06-core-debug")) {
        if (entry.path().string().find(".depth.png") == std::string::npos) continue;
        ++depth_images;
        INFO(entry.path().filename());
        const Image on_core = read_png(entry.path());
        const Image on_es = read_png(dir / "lab06-es-debug" / entry.path().filename());
        // The one place the profiles differ: a 24-bit depth converted to float by glReadPixels (core) and by a
        // texture fetch (ES) can differ in its last bit, and these images stretch the depth range over 255 levels.
        // Measured: one level on 1 pixel of 16384 (entry_exit.exit), the other ports identical.
        const ImageDiff diff = compare_images(on_es, on_core, {});
        CHECK(diff.max_channel_diff <= 1);
        CHECK(diff.differing_pixels <= 16);
    }
    CHECK(depth_images >= 2);
}
