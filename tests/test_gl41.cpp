// The gl41 kind (README.md, "Kinds of test"): every lab's solution graded on an OpenGL 4.1 core context, macOS's,
// against the goldens. Mesa's version override makes llvmpipe offer 4.1 as a Mac does (the lab asks for 4.1, and
// would hold to more where offered: lab 05 takes compute from 4.3), and the report of every case must say 4.1. Lab 05
// steps its particles by transform feedback there; its L05-T2 cases ("feature": "compute": the student's dispatch,
// which does not run) are not counted, and their rows say why. Public cases only, at each lab's own size.
#include "common/io/json.h"
#include "grader/src/cases/cases.h"
#include "grader/src/grade/grade.h"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "per_lab.h"
#include "test_support.h"

#include "catch.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

void graded_at_gl41(const std::string& lab) {
    // Read by every lab process the grader starts (the grader passes the driver's MESA_ variables on, and keys its
    // stored references by them). Another driver ignores them: the version each case reports is checked below.
    setenv("MESA_GL_VERSION_OVERRIDE", "4.1", 1);
    setenv("MESA_GLSL_VERSION_OVERRIDE", "410", 1);
    // The kit's own solution, graded as the student's lab: no submission build.
    const fs::path bin = test::temp_dir("gl41-bin-" + lab);
    fs::copy_file(test::bin_dir() / (lab + "_solution"), bin / lab);
    GradeOptions options;
    options.diagnose = DiagnoseCases::Off;
    options.kit_root = test::source_root();
    options.bin_dir = test::bin_dir();
    options.student_bin_dir = bin;
    options.student_root = test::source_root();
    options.labs = {lab};
    options.self_check = true;
    options.allow_readable_kit = true;  // grading at 4.1, not the walls, is tested here
    options.out_dir = test::temp_dir("gl41-grade-" + lab);
    const GradeReport report = grade(options);
    const LabCases cases = load_lab_cases(test::source_root() / "grader" / "cases" / (lab + ".json"));
    REQUIRE(report.results.size() >= static_cast<std::size_t>(test::lab_rule("public_cases")));
    int passed = 0, not_counted = 0;
    for (const CaseResult& r : report.results) {
        INFO(r.lab << "/" << r.name << ": " << status_name(r.status) << " " << r.detail << "\n" << r.output);
        const auto declared = std::find_if(cases.cases.begin(), cases.cases.end(), [&](const GradeCase& c) { return c.name == r.name; });
        REQUIRE(declared != cases.cases.end());
        if (declared->feature && allows(*declared->feature, Profile::Core, {4, 1}) == false) {
            // Drawn without the student's code for it: not counted, and said.
            CHECK(r.status == CaseStatus::Unsupported);
            CHECK(r.max_points == 0);
            CHECK(r.detail.find("not counted on this context") != std::string::npos);
            CHECK(r.detail.find("this run holds to 4.1") != std::string::npos);
            ++not_counted;
            continue;
        }
        CHECK(r.status == CaseStatus::Passed);
        CHECK(r.output.find("OpenGL 4.1") != std::string::npos);
        CHECK(r.output.find("core profile") != std::string::npos);
        passed += r.status == CaseStatus::Passed;
    }
    CHECK(report.score() == report.max_score());
    // One line per lab for the log: the golden matches at 4.1.
    WARN(lab << " at OpenGL 4.1 core: " << passed << " of " << report.results.size() - not_counted
             << " counted cases match their goldens; " << not_counted << " not counted (need compute shaders)");
}

}  // namespace

constexpr const char* kGl41Test = "gl41: {lab}'s solution graded on OpenGL 4.1 core against the goldens";
GSV_PER_LAB_TEST(kGl41Test, "[gl41]", graded_at_gl41, test::PerLab::Every, test::Gl43Tag::Never)

TEST_CASE("gl41: every lab has its test at OpenGL 4.1 above", "[gl41]") {
    CHECK(test::labs_missing_test(kGl41Test, test::PerLab::Every).empty());
}
