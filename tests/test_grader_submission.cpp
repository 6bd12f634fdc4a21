// Proof that the grader works on C++ submissions: the grader builds each lab of a submission against the
// kit, so a compile error is that lab's build error, and faults in student C++ (a crash, a memory bomb,
// a flood of output, a copied golden image) each get their own status while the rest is graded.
#include "grader_fixture.h"

#include "grader/src/batch/batch.h"
#include "grader/src/report/report.h"
#include "grader/src/run/sandbox.h"

#include <fstream>
#include <map>
#include <unistd.h>

using namespace gsv;

namespace {

std::string probe_value(const std::string& output, const std::string& key) {
    const auto at = output.find("probe " + key + "=");
    if (at == std::string::npos) return "<not printed>";
    const auto from = at + 7 + key.size();
    return output.substr(from, output.find('\n', from) - from);
}

}  // namespace

TEST_CASE("grader: C++ faults in a submission each get their own status, the sandbox holds", "[grader][submission]") {
    const Json spec = test::mutant_spec("lab01");
    const Json& faults = spec.object_at("cpp_faults");
    test::Submission submission(spec.string_at("lab_dir"), &faults);
    GradeOptions options = test::instructor_options("lab01", submission.out());
    options.submission = submission.path();
    options.hidden = false;
    options.timing = false;
    options.timeout_s = 30;
    const GradeReport report = grade(options);
    REQUIRE(report.builds.size() == 1);
    INFO(report.builds[0].log);
    REQUIRE(report.builds[0].ok);
    const auto results = test::by_name(report);
    for (const auto& [name, status] : faults.object_at("expect").as_object()) {
        REQUIRE(results.count(name) == 1);
        const CaseResult& r = results.at(name);
        INFO("case " << name << ": " << r.detail << "\n" << r.output.substr(0, 400));
        CHECK(std::string(status_name(r.status)) == status.as_string());
    }
    CHECK(results.at("per-vertex").output.size() < 80 * 1024);  // the flood was capped

    // What the lab saw from inside the sandbox (case "renormalize").
    const std::string seen = results.at("renormalize").output;
    INFO("sandbox: " << report.sandbox << "\n" << seen);
    if (report.sandbox.find("allow-list") != std::string::npos) {
        CHECK(probe_value(seen, "solutions") == "hidden");
        CHECK(probe_value(seen, "network") == "unreachable");
    } else {
        WARN("this platform refuses unshare: the namespace walls are not tested here");
    }
    // The uid this run leased (grader/src/run/uid_lease.h), as the report names it.
    if (const auto at = report.sandbox.find("runs as uid "); geteuid() == 0 && at != std::string::npos) {
        const std::string uid = report.sandbox.substr(at + 12, report.sandbox.find(';', at) - at - 12);
        CHECK(probe_value(seen, "uid") == uid);
        CHECK(std::stoul(uid) >= kSandboxUidBase);
    }
    // A fresh working folder: a tmpfs of its own inside the walls, a temporary folder of the grader's without them.
    if (report.sandbox.find("allow-list") != std::string::npos) CHECK(probe_value(seen, "home") == kCaseFolder);
    else CHECK(probe_value(seen, "home").find("gsv-case-") != std::string::npos);
}

TEST_CASE("grader: a submission that hands in a golden image is caught", "[grader][submission]") {
    const Json spec = test::mutant_spec("lab01");
    const Json& fault = spec.object_at("copy_fault");
    test::Submission submission(spec.string_at("lab_dir"), &fault);
    GradeOptions options = test::instructor_options("lab01", submission.out());
    options.submission = submission.path();
    options.timing = false;
    const GradeReport report = grade(options);
    REQUIRE(report.builds.at(0).ok);
    int hidden = 0;
    for (const auto& r : report.results) {
        INFO(r.name << ": " << status_name(r.status) << " " << r.detail);
        bool may_pass = false;
        for (const Json& p : fault.array_at("passes").as_array()) may_pass = may_pass || p.as_string() == r.name;
        if (may_pass) continue;
        // Every other case, and above all every hidden one drawn from the seed, fails as a copy.
        CHECK(std::string(status_name(r.status)) == fault.string_at("status"));
        hidden += r.visibility == "hidden";
    }
    CHECK(hidden >= 3);
}

TEST_CASE("grader: a compile error is the lab's build error, with the file and line", "[grader][submission]") {
    const Json spec = test::mutant_spec("lab01");
    const Json& fault = spec.object_at("build_error");
    test::Submission submission(spec.string_at("lab_dir"), &fault);
    GradeOptions options = test::instructor_options("lab01", submission.out());
    options.submission = submission.path();
    const GradeReport report = grade(options);
    REQUIRE(report.builds.size() == 1);
    CHECK_FALSE(report.builds[0].ok);
    REQUIRE(!report.results.empty());
    for (const auto& r : report.results) {
        INFO(r.name << " " << r.kind << ": " << r.detail);
        CHECK(std::string(status_name(r.status)) == fault.string_at("status"));
        if (r.kind == "image") CHECK(r.detail.find(fault.string_at("error_mentions")) != std::string::npos);
        CHECK(r.points == 0);
    }
    // Results are written even when nothing built.
    write_reports(report, submission.out());
    CHECK(std::filesystem::exists(submission.out() / "results.json"));
}

TEST_CASE("grader: a folder of submissions graded by parallel workers, one class table", "[grader][submission]") {
    test::TempDir dir;
    const auto lab_dir = test::mutant_spec("lab01").string_at("lab_dir");
    // One complete submission, one that is the starter, one without labs/.
    std::filesystem::create_directories(dir.path("class/ada/labs"));
    std::filesystem::copy(test::source_root() / "solutions" / lab_dir, dir.path("class/ada/labs") / lab_dir,
                          std::filesystem::copy_options::recursive);
    std::filesystem::create_directories(dir.path("class/bob/labs"));
    std::filesystem::copy(test::source_root() / "labs" / lab_dir, dir.path("class/bob/labs") / lab_dir,
                          std::filesystem::copy_options::recursive);
    std::filesystem::create_directories(dir.path("class/cy/empty"));
    BatchOptions options;
    options.grader = test::bin_dir() / "gsv-grade";
    options.submissions = dir.path("class");
    options.out_dir = dir.path("out");
    options.workers = 2;
    options.seed = 5;
    options.pass_through = {"--labs", "lab01", "--no-timing"};
    const auto entries = grade_batch(options, nullptr);
    REQUIRE(entries.size() == 3);
    CHECK(entries[0].name == "ada");
    CHECK(entries[0].graded);
    CHECK(entries[0].max_score > 0);
    CHECK(entries[0].score == entries[0].max_score);
    CHECK(entries[1].graded);
    CHECK(entries[1].score < entries[1].max_score / 4);
    CHECK_FALSE(entries[2].graded);
    CHECK(entries[2].problem.find("labs/") != std::string::npos);
    // Even an ungradable submission leaves a results.json that says why (what Gradescope shows the student).
    CHECK(read_json_file(dir.path("out/cy/results.json")).string_at("output").find("no labs/ folder") != std::string::npos);
    CHECK(std::filesystem::exists(dir.path("out/ada/report.html")));
    const std::string csv = class_csv(entries);
    CHECK(csv.find("\"ada\",yes,") != std::string::npos);
    CHECK(csv.find("\"cy\",no,") != std::string::npos);
}

namespace {

// The image checks' statuses and points, by case: what two ways of grading must agree on.
std::map<std::string, std::string> verdicts(const GradeReport& report) {
    std::map<std::string, std::string> out;
    for (const auto& r : report.results) out[r.kind + " " + r.name] = std::string(status_name(r.status)) + " " + std::to_string(r.points);
    return out;
}

GradeReport grade_submission(const std::filesystem::path& submission, const std::filesystem::path& out,
                             const std::filesystem::path& cache, bool reuse = true) {
    GradeOptions options = test::instructor_options("lab01", out);
    options.submission = submission;
    options.self_check = true;
    options.timing = false;
    options.reuse_builds = reuse;
    options.build_cache = cache;
    return grade(options);
}

}  // namespace

TEST_CASE("grader: a lab whose C++ is the kit's starter's runs the kit's binary, and grades as if built", "[grader][submission]") {
    test::TempDir dir;
    const auto lab_dir = test::mutant_spec("lab01").string_at("lab_dir");
    // The solution's shaders with the starter's C++ (lab 01's TODOs are all GLSL): full marks from the kit's binary.
    std::filesystem::create_directories(dir.path("submission/labs"));
    std::filesystem::copy(test::source_root() / "solutions" / lab_dir, dir.path("submission/labs") / lab_dir,
                          std::filesystem::copy_options::recursive);
    const GradeReport reused = grade_submission(dir.path("submission"), dir.path("reused"), dir.path("cache"));
    REQUIRE(reused.builds.size() == 1);
    INFO(reused.builds[0].log);
    CHECK(reused.builds[0].ok);
    CHECK(reused.builds[0].origin == "unchanged C++: the kit's binary");
    CHECK(reused.score() == reused.max_score());
    const GradeReport built = grade_submission(dir.path("submission"), dir.path("built"), dir.path("cache"), false);
    CHECK(built.builds.at(0).origin == "built");
    CHECK(verdicts(built) == verdicts(reused));
    // The report says how each lab's binary came to be.
    write_reports(reused, dir.path("reused"));
    CHECK(test::read_text(dir.path("reused/report.json")).find("unchanged C++: the kit's binary") != std::string::npos);
}

TEST_CASE("grader: a lab whose C++ only looks unchanged is built, and a build is kept for the next same C++", "[grader][submission]") {
    test::TempDir dir;
    const auto lab_dir = test::mutant_spec("lab01").string_at("lab_dir");
    const auto lab = dir.path("submission/labs") / lab_dir;
    std::filesystem::create_directories(lab.parent_path());
    std::filesystem::copy(test::source_root() / "labs" / lab_dir, lab, std::filesystem::copy_options::recursive);
    // One byte of lab.cpp changed, the same size and the same time: a comment's first letter.
    std::string text = test::read_text(lab / "lab.cpp");
    const auto comment = text.find("// ");
    REQUIRE(comment != std::string::npos);
    text[comment + 3] = text[comment + 3] == 'x' ? 'y' : 'x';
    const auto time = std::filesystem::last_write_time(lab / "lab.cpp");
    std::ofstream(lab / "lab.cpp", std::ios::binary) << text;
    std::filesystem::last_write_time(lab / "lab.cpp", time);
    REQUIRE(std::filesystem::file_size(lab / "lab.cpp") == std::filesystem::file_size(test::source_root() / "labs" / lab_dir / "lab.cpp"));
    const auto cache = dir.path("cache");  // fresh: no earlier run's entry answers for it

    const GradeReport first = grade_submission(dir.path("submission"), dir.path("first"), cache);
    INFO(first.builds.at(0).log);
    CHECK(first.builds.at(0).ok);
    CHECK(first.builds.at(0).origin == "built");
    const GradeReport second = grade_submission(dir.path("submission"), dir.path("second"), cache);
    CHECK(second.builds.at(0).origin == "unchanged C++: an earlier build");
    CHECK(verdicts(second) == verdicts(first));

    // A damaged entry is not trusted: the lab is built again, and the log says why.
    int damaged = 0;
    for (const auto& entry : std::filesystem::directory_iterator(cache)) {
        std::ofstream(entry.path() / "binary", std::ios::binary | std::ios::app) << "tampered";
        ++damaged;
    }
    REQUIRE(damaged == 1);
    const GradeReport third = grade_submission(dir.path("submission"), dir.path("third"), cache);
    CHECK(third.builds.at(0).origin == "built");
    CHECK(third.builds.at(0).log.find("does not hold what its key says") != std::string::npos);
    CHECK(verdicts(third) == verdicts(first));

    // A cache that cannot be written (its folder is a file): one line, and the lab is graded all the same.
    std::ofstream(dir.path("not-a-folder")) << "x";
    const GradeReport fourth = grade_submission(dir.path("submission"), dir.path("fourth"), dir.path("not-a-folder"));
    CHECK(fourth.builds.at(0).ok);
    CHECK(fourth.builds.at(0).log.find("build cache: ") != std::string::npos);
    CHECK(verdicts(fourth) == verdicts(first));
}
