// Reruns after a fix (gsv-grade --regrade-only changed, grader/src/grade/regrade.h): a lab is graded again only where
// something its grade depends on changed, the others keep the last run's rows, the merged grades are what a full run
// gives, and the class files say which were regraded. report.json reads back whole, which the merge rests on.
#include "catch.hpp"
#include "grader_fixture.h"

#include <sstream>
#include "test_support.h"

#include "common/io/json.h"
#include "grader/src/report/report.h"
#include "grader/src/run/process.h"

#include <fstream>

namespace fs = std::filesystem;
using namespace gsv;

namespace {

// Two labs, one case each: enough to see one lab kept and the other regraded, cheap enough for every run.
const std::vector<std::string> kRun = {"--labs", "lab01,lab02", "--cases", "phong,rotation", "--self-check", "--seed", "7", "--quiet"};

ProcessResult gsv_grade(const std::vector<std::string>& args, const fs::path& dir) {
    std::vector<std::string> argv{(test::bin_dir() / "gsv-grade").string()};
    argv.insert(argv.end(), args.begin(), args.end());
    ProcessLimits limits;
    limits.timeout = std::chrono::seconds(300);
    limits.max_output_bytes = 1 << 20;
    return run_process(argv, dir, limits);
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

// Each check's name, status and score, as results.json gives them to the student.
std::map<std::string, std::string> grades(const fs::path& out) {
    std::map<std::string, std::string> out_grades;
    const Json results = read_json_file(out / "results.json");
    for (const Json& t : results.array_at("tests").as_array())
        out_grades[t.string_at("name")] = t.string_at("status") + " " + std::to_string(t.number_at("score")) + " " + t.string_at("output");
    return out_grades;
}

std::vector<std::string> strings(const Json& list) {
    std::vector<std::string> out;
    for (const Json& s : list.as_array()) out.push_back(s.as_string());
    return out;
}

}  // namespace

TEST_CASE("grader reports: report.json reads back whole: written again, byte for byte the same", "[grader][regrade]") {
    // A run with every kind of row: passes, failures, a timing row, arrays, builds (lab 05's self-check has arrays).
    test::TempDir dir;
    GradeOptions options = test::instructor_options("lab05", dir.path("out"));
    options.self_check = true;
    options.cases = {"abc", "ragged"};
    GradeReport report = grade(options);
    report.regraded = {"lab05"};
    report.kept = {"lab01"};
    REQUIRE(!report.results.empty());
    const std::string written = report_json(report);
    std::ofstream(dir.path("report.json")) << written;
    const GradeReport back = read_report_json(dir.path("report.json"));
    CHECK(report_json(back) == written);
    CHECK(gradescope_json(back) == gradescope_json(report));
    CHECK(junit_xml(back) == junit_xml(report));

    // What does not read back is one line naming the file.
    dir.write("bad.json", "{\"submission\": 1}");
    CHECK(test::gsv_error_message([&] { read_report_json(dir.path("bad.json")); }).rfind(dir.path("bad.json").string(), 0) == 0);
}

TEST_CASE("gsv-grade --regrade-only changed: only the labs whose inputs changed are graded, the rest kept, the grades a full run's",
          "[grader][regrade]") {
    test::TempDir dir;
    // A class of two: ada handed in the solutions of labs 01 and 02, bo the starters.
    for (const char* lab : {"lab01_gooch", "lab02_lic"}) {
        fs::create_directories(dir.path("class/ada/labs"));
        fs::create_directories(dir.path("class/bo/labs"));
        fs::copy(test::source_root() / "solutions" / lab, dir.path("class/ada/labs") / lab, fs::copy_options::recursive);
        fs::copy(test::source_root() / "labs" / lab, dir.path("class/bo/labs") / lab, fs::copy_options::recursive);
    }
    const std::vector<std::string> batch = with(kRun, {"--batch", dir.path("class").string(), "--workers", "2", "--out", dir.path("grades").string()});
    const ProcessResult first = gsv_grade(batch, dir.path());
    INFO(first.output);
    REQUIRE(first.exit_code == 0);
    const auto ada_first = grades(dir.path("grades/ada")), bo_first = grades(dir.path("grades/bo"));
    REQUIRE(ada_first.size() == 2);
    CHECK(test::read_text(dir.path("grades/class.csv")).find("\"ada\",yes,4,4,") != std::string::npos);
    CHECK(fs::exists(dir.path("grades/ada/inputs.json")));
    // A class's folders stay small (--passed-pictures thumbnail, --keep-build no in a batch's runs): a passed case keeps a
    // thumbnail of its picture, a failing one its pictures whole; the build's binaries go, its sources stay.
    CHECK(fs::exists(dir.path("grades/ada/lab01/phong/actual.jpg")));
    CHECK_FALSE(fs::exists(dir.path("grades/ada/lab01/phong/actual.png")));
    CHECK_FALSE(fs::exists(dir.path("grades/ada/lab01/phong/expected.png")));
    CHECK(fs::exists(dir.path("grades/bo/lab01/phong/actual.png")));
    CHECK(fs::exists(dir.path("grades/bo/lab01/phong/expected.png")));
    CHECK_FALSE(fs::exists(dir.path("grades/ada/submission-build/build")));
    CHECK(fs::exists(dir.path("grades/ada/submission-build/kit/labs/lab01_gooch")));

    // Nothing changed: nothing graded, every row kept, the grades as they were.
    const ProcessResult again = gsv_grade(with(batch, {"--regrade-only", "changed"}), dir.path());
    INFO(again.output);
    REQUIRE(again.exit_code == 0);
    CHECK(grades(dir.path("grades/ada")) == ada_first);
    CHECK(grades(dir.path("grades/bo")) == bo_first);
    const Json ada_report = read_json_file(dir.path("grades/ada/report.json"));
    CHECK(strings(ada_report.array_at("regraded")).empty());
    CHECK(strings(ada_report.array_at("kept")) == std::vector<std::string>{"lab01", "lab02"});
    const std::string csv = test::read_text(dir.path("grades/class.csv"));
    INFO(csv);
    CHECK(csv.find(",problem,regraded\n") != std::string::npos);
    CHECK(csv.find("\"bo\",yes,0,4,") != std::string::npos);
    CHECK(csv.find(",\"\",\"none\"\n") != std::string::npos);
    CHECK(test::read_text(dir.path("grades/class.txt")).find("regraded / problem") != std::string::npos);

    // bo finishes lab 02: only bo's lab 02 is graded, and bo's grades are what a full run of bo's work gives.
    fs::copy(test::source_root() / "solutions/lab02_lic", dir.path("class/bo/labs/lab02_lic"),
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    const ProcessResult fixed = gsv_grade(with(batch, {"--regrade-only", "changed"}), dir.path());
    INFO(fixed.output);
    REQUIRE(fixed.exit_code == 0);
    const Json bo_report = read_json_file(dir.path("grades/bo/report.json"));
    CHECK(strings(bo_report.array_at("regraded")) == std::vector<std::string>{"lab02"});
    CHECK(strings(bo_report.array_at("kept")) == std::vector<std::string>{"lab01"});
    CHECK(grades(dir.path("grades/ada")) == ada_first);
    const ProcessResult full = gsv_grade(with(kRun, {"--submission", dir.path("class/bo").string(), "--out", dir.path("bo-full").string()}), dir.path());
    REQUIRE(full.exit_code == 0);
    CHECK(grades(dir.path("grades/bo")) == grades(dir.path("bo-full")));
    CHECK(grades(dir.path("grades/bo")) != bo_first);
    CHECK(test::read_text(dir.path("grades/class.csv")).find("\"bo\",yes,2,4,") != std::string::npos);
    CHECK(test::read_text(dir.path("grades/class.csv")).find(",\"\",\"lab02\"\n") != std::string::npos);

    // The class's tables say what changed (issue 42): class.csv the last run's score beside this one's, its points per
    // lab; class-cases.csv every row of every report.json; history.csv each row whose points moved, and why.
    const std::string after = test::read_text(dir.path("grades/class.csv"));
    INFO(after);
    CHECK(after.rfind("submission,graded,score,max_score,previous_score,changed,lab01_points,lab01_max,lab02_points,lab02_max,"
                      "seconds,problem,regraded\n", 0) == 0);
    CHECK(after.find("\"bo\",yes,2,4,0,yes,0,2,2,2,") != std::string::npos);
    CHECK(after.find("\"ada\",yes,4,4,4,no,2,2,2,2,") != std::string::npos);
    const std::string cases = test::read_text(dir.path("grades/class-cases.csv"));
    for (const char* name : {"ada", "bo"}) {
        std::string expected;
        const Json report = read_json_file(dir.path("grades") / name / "report.json");
        for (const Json& r : report.array_at("results").as_array()) {
            std::ostringstream points;
            points << r.number_or("points", 0) << "," << r.number_or("max_points", 0);
            expected = std::string(name) + "," + r.string_at("lab") + "," + r.string_or("todo", "") + "," + r.string_at("name") + "," +
                       r.string_at("kind") + "," + r.string_at("status") + "," + points.str() + "\n";
            INFO(cases);
            CHECK(cases.find(expected) != std::string::npos);
        }
    }
    // batch.json holds the same rows.
    const Json record = read_json_file(dir.path("grades/batch.json"));
    std::size_t in_csv = 0;
    for (const char c : cases) in_csv += c == '\n';
    CHECK(record.array_at("cases").size() + 1 == in_csv);
    const std::string history = test::read_text(dir.path("grades/history.csv"));
    INFO(history);
    CHECK(history.rfind("when,submission,lab,check,kind,old_points,new_points,max_points,why\n", 0) == 0);
    // The first run added every row; the run that changed nothing added none; bo's lab 02 moved from 0.
    std::size_t first_graded = 0, lab02_again = 0, other = 0;
    std::istringstream lines(history);
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line)) {
        if (line.find(",first graded") != std::string::npos) ++first_graded;
        else if (line.find(",bo,lab02,") != std::string::npos && line.find(",0,") != std::string::npos &&
                 line.find("lab02 graded again: its inputs changed") != std::string::npos) ++lab02_again;
        else ++other;
    }
    CHECK(first_graded == read_json_file(dir.path("grades/ada/report.json")).array_at("results").size() +
                              read_json_file(dir.path("grades/bo/report.json")).array_at("results").size());
    CHECK(lab02_again >= 1);
    CHECK(other == 0);

    // Another seed is another input of every lab: all of them graded again.
    const ProcessResult reseeded = gsv_grade(with(with(kRun, {"--submission", dir.path("class/bo").string(), "--out",
                                                              dir.path("grades/bo").string(), "--regrade-only", "changed"}),
                                                  {"--seed", "8"}),
                                             dir.path());
    REQUIRE(reseeded.exit_code == 0);
    CHECK(strings(read_json_file(dir.path("grades/bo/report.json")).array_at("regraded")) == std::vector<std::string>{"lab01", "lab02"});

    // A record that does not read back: every lab graded, and the run says why in one line.
    std::ofstream(dir.path("grades/ada/inputs.json")) << "{ not json";
    const ProcessResult damaged = gsv_grade(with(kRun, {"--submission", dir.path("class/ada").string(), "--out",
                                                        dir.path("grades/ada").string(), "--regrade-only", "changed"}),
                                            dir.path());
    INFO(damaged.output);
    CHECK(damaged.exit_code == 0);
    CHECK(damaged.output.find("--regrade-only changed: the last run's record does not read back") != std::string::npos);
    CHECK(strings(read_json_file(dir.path("grades/ada/report.json")).array_at("regraded")) == std::vector<std::string>{"lab01", "lab02"});
    CHECK(grades(dir.path("grades/ada")) == ada_first);

    // Only 'changed' is a thing to regrade.
    const ProcessResult typo = gsv_grade({"--regrade-only", "everything", "--out", dir.path("x").string()}, dir.path());
    CHECK(typo.exit_code == 2);
    CHECK(typo.output.find("--regrade-only takes 'changed'") != std::string::npos);
}
