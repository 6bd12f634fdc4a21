// Rendering without restarting (grader/src/run/lab_serve.h): one process per lab serving its cases one after another
// grades exactly as one process per case does, case for case (results.json's status, score and status line), for the
// kit's starters, the solutions and lab 01's faults (every mutant, correct variant and C++ mutant of tests/mutants/ is
// graded both ways by the mutation tests, tests/test_grader_mutants.cpp); and a served lab cannot carry a case's crash,
// loop, parameters or a hand-in made before it was asked into another case.
#include "grader_fixture.h"
#include "serve_compare.h"

#include "grader/src/report/report.h"
#include "grader/src/run/sandbox.h"

#include <cstdlib>
#include <memory>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

GradeReport grade_with(GradeOptions options, LabProcesses processes) {
    options.lab_processes = processes;
    return grade(options);
}

// The references each way renders, kept for its next grading: a way's own, so that each way's references are rendered
// its way (one process per case, or served).
struct ReferencesEachWay {
    std::shared_ptr<ReferenceCache> per_case = std::make_shared<ReferenceCache>(), per_lab = std::make_shared<ReferenceCache>();
};

// Grades `options` both ways and checks every check alike; returns the per-lab grading.
GradeReport same_both_ways(GradeOptions options, const std::string& what, const ReferencesEachWay* references = nullptr) {
    if (references) options.reference_cache = references->per_case;
    const GradeReport per_case = grade_with(options, LabProcesses::PerCase);
    if (references) options.reference_cache = references->per_lab;
    const GradeReport per_lab = grade_with(options, LabProcesses::PerLab);
    test::check_graded_alike(per_case, per_lab, what);
    return per_lab;
}

// Whether student code can be served here: only behind the allow-list walls (GradingSession::serve).
bool walls_up() {
    SandboxPolicy policy;
    policy.read_only = {test::source_root() / "shaders"};
    return probe_sandbox(policy).allow_list();
}

GradeOptions quick(GradeOptions options) {
    options.hidden = false;
    options.timing = false;
    return options;
}

// Lab 01's untimed faults (tests/mutants/lab01.json), each on every public case, graded both ways (the mutants, correct
// variants and C++ mutants of every lab: their mutation tests). One reference cache: the references are the same binary
// either way (their serving is compared on the starters and solutions).
void both_ways_on_faults(const std::string& lab) {
    if (!walls_up()) WARN("no allow-list walls here: student code is not served, and both ways are one process per case");
    const auto cache = std::make_shared<ReferenceCache>();
    const Json spec = test::mutant_spec(lab);
    const std::string lab_dir = spec.string_at("lab_dir");
    int compared = 0;
    for (const Json& fault : spec.array_at("faults").as_array()) {
        if (fault.bool_or("timed_only", false)) continue;  // timing: tests/test_grader_mutants.cpp
        test::EditedKit kit(lab, lab_dir, fault);
        GradeOptions options = quick(kit.options());
        options.timeout_s = fault.number_or("timeout_s", 0);
        options.reference_cache = cache;
        same_both_ways(options, lab + " fault '" + fault.string_at("name") + "'");
        ++compared;
    }
    CHECK(compared >= 3);
}

}  // namespace

TEST_CASE("serving: the starters and the solutions grade alike with one process per lab and one per case", "[grader][serve][gl43]") {
    test::TempDir dir;
    // Every lab, every public case; each way renders its own references (none from the store), once for both gradings.
    const ReferencesEachWay references;
    GradeOptions starters = quick(test::instructor_options("", dir.path("starters")));
    starters.labs.clear();
    starters.stored_references = false;
    const GradeReport served = same_both_ways(starters, "the starters", &references);
    CHECK(served.results.size() >= 80);

    // The solutions as a submission, built once (labs 03 and 05 have C++), graded both ways from that build.
    for (const auto& lab : test::labs_with_mutants()) {
        const std::string lab_dir = test::mutant_spec(lab).string_at("lab_dir");
        fs::create_directories(dir.path("solutions/labs"));
        fs::copy(test::source_root() / "solutions" / lab_dir, dir.path("solutions/labs") / lab_dir, fs::copy_options::recursive);
    }
    GradeOptions build = quick(test::instructor_options("", dir.path("built")));
    build.labs.clear();
    build.submission = dir.path("solutions");
    build.cases = {"gooch"};  // one case; the build is every lab's
    const GradeReport built = grade(build);
    for (const auto& b : built.builds) CHECK(b.ok);
    GradeOptions solutions = starters;
    solutions.out_dir = dir.path("solutions-out");
    solutions.student_bin_dir = dir.path("built/submission-build/build/bin");
    solutions.student_root = dir.path("built/submission-build/kit");
    const GradeReport graded_solutions = same_both_ways(solutions, "the solutions", &references);
    CHECK(graded_solutions.score() == graded_solutions.max_score());
}

TEST_CASE("serving: lab01's faults grade alike with one process per lab and one per case", "[grader][serve]") {
    both_ways_on_faults("lab01");
}

namespace {

// A submission whose lab 01 plants tests/attacks/serve_attacks.cpp.in around its render, built once.
class ServeAttacks {
public:
    ServeAttacks() {
        const fs::path lab = dir_.path("submission/labs/lab01_gooch");
        fs::create_directories(lab.parent_path());
        fs::copy(test::source_root() / "solutions" / "lab01_gooch", lab, fs::copy_options::recursive);
        fs::copy_file(test::source_root() / "tests" / "attacks" / "serve_attacks.cpp.in", lab / "serve_attacks.cpp");
        const std::string draw = "        draw(kit, frame, *shade_, kBackground);\n";
        test::replace_in_file(lab / "lab.cpp", draw, "        serve_attack_before(kit);\n" + draw + "        serve_attack_after(kit);\n");
        test::replace_in_file(lab / "lab.cpp", "namespace {\n",
                              "void serve_attack_before(gsv::LabKit& kit);\nvoid serve_attack_after(gsv::LabKit& kit);\n\nnamespace {\n");
        GradeOptions build = options("built");
        build.submission = dir_.path("submission");
        build.student_bin_dir.clear();
        build.student_root.clear();
        const GradeReport built = grade(build);
        REQUIRE(built.builds.size() == 1);
        INFO(built.builds[0].log.substr(built.builds[0].log.size() > 3000 ? built.builds[0].log.size() - 3000 : 0));
        REQUIRE(built.builds[0].ok);
    }
    // diffuse, diffuse-white (the attacks' chosen case: a white surface) and phong, in that order, from the build.
    GradeOptions options(const std::string& out) const {
        GradeOptions o = quick(test::instructor_options("lab01", dir_.path(out)));
        o.cases = {"diffuse", "diffuse-white", "phong"};
        o.student_bin_dir = dir_.path("built/submission-build/build/bin");
        o.student_root = dir_.path("built/submission-build/kit");
        return o;
    }
    // The three cases graded the way `processes` says with $GSV_ATTACK set to `attack`.
    std::map<std::string, CaseResult> graded(const std::string& attack, LabProcesses processes, double timeout_s = 0) const {
        GradeOptions o = options(attack + (processes == LabProcesses::PerLab ? "-per-lab" : "-per-case"));
        o.timeout_s = timeout_s;
        setenv("GSV_ATTACK", attack.c_str(), 1);
        const GradeReport report = grade_with(o, processes);
        unsetenv("GSV_ATTACK");
        return test::by_name(report);
    }

private:
    test::TempDir dir_;
};

std::string statuses(const std::map<std::string, CaseResult>& results) {
    std::string text;
    for (const char* name : {"diffuse", "diffuse-white", "phong"})
        text += std::string(name) + ": " + (results.count(name) ? status_name(results.at(name).status) : "(missing)") + "; ";
    return text;
}

bool printed(const CaseResult& r, const std::string& line) { return r.output.find(line + "\n") != std::string::npos; }

}  // namespace

TEST_CASE("serving: a crash, an endless loop, parameters a case set and a hand-in before the request stay in their case",
          "[grader][serve][attacks]") {
    if (!walls_up()) {
        WARN("no allow-list walls here: student code is not served, so there is nothing to attack");
        return;
    }
    const ServeAttacks submission;

    // Honest: the three cases in one process, one after another.
    const auto honest = submission.graded("none", LabProcesses::PerLab);
    INFO("honest: " << statuses(honest));
    REQUIRE(honest.size() == 3);
    for (const auto& [name, r] : honest) CHECK(r.status == CaseStatus::Passed);
    CHECK(printed(honest.at("diffuse"), "served 1"));
    CHECK(printed(honest.at("diffuse-white"), "served 2"));
    CHECK(printed(honest.at("phong"), "served 3"));

    // A crash in the second case only: that case crashed (in a fresh process too), the first and third are graded,
    // the third in a new process; as one process per case grades them.
    const auto crash = submission.graded("crash-white", LabProcesses::PerLab);
    INFO("crash-white: " << statuses(crash) << "\n" << crash.at("diffuse-white").detail);
    CHECK(crash.at("diffuse").status == CaseStatus::Passed);
    CHECK(crash.at("diffuse-white").status == CaseStatus::Crash);
    CHECK(crash.at("diffuse-white").detail.find("signal 11") != std::string::npos);
    CHECK(crash.at("phong").status == CaseStatus::Passed);
    CHECK(printed(crash.at("phong"), "served 1"));
    CHECK(statuses(crash) == statuses(submission.graded("crash-white", LabProcesses::PerCase)));

    // A crash that comes of an earlier case (the second of any process): rendered again in a fresh process, it passes,
    // as it does where every case has a process of its own.
    const auto second = submission.graded("crash-second", LabProcesses::PerLab);
    INFO("crash-second: " << statuses(second));
    for (const auto& [name, r] : second) CHECK(r.status == CaseStatus::Passed);
    CHECK(statuses(second) == statuses(submission.graded("crash-second", LabProcesses::PerCase)));

    // An endless loop in one case: a timeout at its own limit, timed from its request; the others graded.
    const auto start = std::chrono::steady_clock::now();
    const auto loop = submission.graded("loop-white", LabProcesses::PerLab, 5);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO("loop-white: " << statuses(loop) << " in " << seconds << " s");
    CHECK(loop.at("diffuse").status == CaseStatus::Passed);
    CHECK(loop.at("diffuse-white").status == CaseStatus::Timeout);
    CHECK(loop.at("phong").status == CaseStatus::Passed);
    CHECK(printed(loop.at("phong"), "served 1"));
    CHECK(seconds < 60);
    CHECK(statuses(loop) == statuses(submission.graded("loop-white", LabProcesses::PerCase, 5)));

    // A lab that changes its own parameters after drawing a case (a red surface, the light below, a tight highlight):
    // each next case starts from the declared defaults with only its own settings, and passes. diffuse-white's
    // settings (a white surface, the light above) do not reach phong either.
    const auto kept = submission.graded("set-param", LabProcesses::PerLab);
    INFO("set-param: " << statuses(kept));
    for (const auto& [name, r] : kept) CHECK(r.status == CaseStatus::Passed);
    CHECK(printed(kept.at("phong"), "served 3"));

    // A hand-in before the grader asked for any case: refused, in every case, without a case's settings sent.
    const auto early = submission.graded("early-handin", LabProcesses::PerLab);
    INFO("early-handin: " << statuses(early) << "\n" << early.at("diffuse").detail);
    for (const auto& [name, r] : early) {
        CHECK(r.status == CaseStatus::Refused);
        CHECK(r.detail.find("handed in a IMG1 message before the grader asked for a case") != std::string::npos);
        CHECK(r.points == 0);
    }
    CHECK(statuses(early) == statuses(submission.graded("early-handin", LabProcesses::PerCase)));
}
