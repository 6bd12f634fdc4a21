// The diagnosis (grader/src/diagnose/): which known mistakes explain a lab's failing cases, ranked; what the student is
// told of it; and where a failure it explains is put (grader/src/judge/needs.h). Without GL: the ranking works on which
// cases each mistake's pictures explain; test_grader_diagnosis_gl.cpp grades real mistakes.
#include "catch.hpp"
#include "lab_runner.h"
#include "grader/src/diagnose/diagnosis.h"
#include "grader/src/judge/needs.h"
#include "grader/src/report/report_format.h"

#include <set>
#include <string>
#include <vector>

using namespace gsv;

namespace {

KnownMistake mistake(const std::string& name, const std::string& todo) {
    return {name, todo, "says " + name, "TODO table", Json::object(), false, {}, {}};
}

}  // namespace

TEST_CASE("diagnosis: the mistake that explains the most failing cases comes first, then the one that explains the rest", "[unit]") {
    const std::vector<KnownMistake> mistakes{mistake("a", "L01-T1"), mistake("b", "L01-T4"), mistake("c", "L01-T2")};
    const std::vector<std::string> failing{"diffuse", "phong", "gooch", "stretched", "odd"};
    const LabDiagnosis d = rank_mistakes("lab01", failing, mistakes,
                                         {{"diffuse", "phong", "stretched"}, {"gooch"}, {"diffuse"}});
    REQUIRE(d.found.size() == 2);
    CHECK(d.found[0].names == std::vector<std::string>{"a"});
    CHECK(d.found[0].todo == "L01-T1");
    CHECK(d.found[0].cases == std::vector<std::string>{"diffuse", "phong", "stretched"});
    CHECK(d.found[1].names == std::vector<std::string>{"b"});
    CHECK(d.found[1].cases == std::vector<std::string>{"gooch"});
    // "c" explains nothing "a" left: not named. "odd" no mistake explains: said so, not given the nearest name.
    CHECK(d.unexplained == std::vector<std::string>{"odd"});
    CHECK(d.failing == failing);
}

TEST_CASE("diagnosis: mistakes whose pictures explain the same cases are twins, named together with one text", "[unit]") {
    const std::vector<KnownMistake> mistakes{mistake("inverse without transpose", "L01-T1"), mistake("model-view", "L01-T1"),
                                             mistake("other", "L01-T1")};
    const LabDiagnosis d = rank_mistakes("lab01", {"stretched"}, mistakes, {{"stretched"}, {"stretched"}, {}});
    REQUIRE(d.found.size() == 1);
    CHECK(d.found[0].names == std::vector<std::string>{"inverse without transpose", "model-view"});
    CHECK(d.found[0].says == "says inverse without transpose");
    CHECK(d.unexplained.empty());
}

TEST_CASE("diagnosis: between two that explain as many, the one that explains fewer cases in all is the closer", "[unit]") {
    // "broad" also explains a case that passed for the student (not failing): it would have changed more than they did.
    const std::vector<KnownMistake> mistakes{mistake("broad", "L02-T1"), mistake("narrow", "L02-T3")};
    const LabDiagnosis d = rank_mistakes("lab02", {"border"}, mistakes, {{"border", "elsewhere"}, {"border"}});
    REQUIRE(d.found.size() == 1);
    CHECK(d.found[0].names == std::vector<std::string>{"narrow"});
}

TEST_CASE("diagnosis: no failing case, or none explained, names no mistake", "[unit]") {
    const std::vector<KnownMistake> mistakes{mistake("a", "L01-T1")};
    CHECK(rank_mistakes("lab01", {}, mistakes, {{}}).found.empty());
    const LabDiagnosis d = rank_mistakes("lab01", {"phong"}, mistakes, {{}});
    CHECK(d.found.empty());
    CHECK(d.unexplained == std::vector<std::string>{"phong"});
}

TEST_CASE("diagnosis: the student's lines name the idea, the TODO, the sheet and the cases, never a hidden case", "[unit]") {
    LabDiagnosis d;
    d.lab = "lab01";
    d.failing = {"stretched", "hidden-stretched", "gooch"};
    d.found = {{"L01-T1", "the normal stays in the model's space", "The hard cases", {"kit name"}, {"stretched", "hidden-stretched"}, false}};
    d.unexplained = {"gooch"};
    d.not_started = {"L01-T6"};
    d.compare = "build/bin/lab01 compare --case gooch";
    GradeReport report;
    for (const auto& [name, visibility] : std::vector<std::pair<std::string, std::string>>{
             {"stretched", "public"}, {"hidden-stretched", "hidden"}, {"gooch", "public"}}) {
        CaseResult r;
        r.lab = "lab01";
        r.name = name;
        r.visibility = visibility;
        report.results.push_back(r);
    }
    const std::vector<std::string> all = diagnosis_lines(d);
    REQUIRE(all.size() == 4);
    CHECK(all[0] == "one known mistake explains 2 of your 3 failing cases:");
    CHECK(all[1] == "  L01-T1: the normal stays in the model's space (sheet: The hard cases)");
    CHECK(all[2] == "no known mistake matches 'gooch'; compare yours with the reference: build/bin/lab01 compare --case gooch");
    CHECK(all[3] == "not started: L01-T6");
    const LabDiagnosis student = student_diagnosis(d, report);
    CHECK(student.failing == std::vector<std::string>{"stretched", "gooch"});
    REQUIRE(student.found.size() == 1);
    CHECK(student.found[0].cases == std::vector<std::string>{"stretched"});
    std::string text;
    for (const auto& line : diagnosis_lines(student)) text += line + "\n";
    CHECK(text.find("hidden") == std::string::npos);
    CHECK(text.find("kit name") == std::string::npos);  // the kit's own name of a mistake is the instructor's
    CHECK(text.find("1 of your 2 failing cases") != std::string::npos);
}

TEST_CASE("diagnosis: a failure a known mistake explains is put on the mistake's TODO, not relabelled as needing another", "[unit]") {
    LabCases lab;
    lab.lab = "lab01";
    GradeCase stretched, diffuse;
    stretched.name = "stretched";
    stretched.todo = "L01-T1";
    diffuse.name = "diffuse";
    diffuse.todo = "L01-T2";
    diffuse.needs = {"L01-T1"};
    lab.cases = {stretched, diffuse};
    std::vector<CaseResult> rows(2);
    rows[0].name = "stretched";
    rows[0].todo = "L01-T1";
    rows[1].name = "diffuse";
    rows[1].todo = "L01-T2";
    for (auto& r : rows) {
        r.lab = "lab01";
        r.status = CaseStatus::WrongImage;
        r.detail = "max diff 84";
    }
    SECTION("explained: the status stands, the detail names the mistake and its TODO") {
        rows[1].mistake = "the normal stays in the model's space";
        rows[1].mistake_todo = "L01-T1";
        blame_needed_todos(lab, rows, 0);
        CHECK(rows[1].status == CaseStatus::WrongImage);
        CHECK(rows[1].detail == "a known mistake in L01-T1 explains it: the normal stays in the model's space; here: max diff 84");
    }
    SECTION("not explained: needs L01-T1 first, as before") {
        blame_needed_todos(lab, rows, 0);
        CHECK(rows[1].status == CaseStatus::NeedsFirst);
        CHECK(rows[1].detail.rfind("needs L01-T1 first", 0) == 0);
    }
    SECTION("a mistake in a TODO whose own cases pass is still the root another case's failure goes to") {
        rows[0].status = CaseStatus::Passed;
        rows.push_back(rows[1]);
        rows[1].mistake = "the normal stays in the model's space";
        rows[1].mistake_todo = "L01-T1";
        rows[2].name = "diffuse";  // a second failure of the same case's kind, not explained
        blame_needed_todos(lab, rows, 0);
        CHECK(rows[2].status == CaseStatus::NeedsFirst);
        CHECK(rows[2].detail.find("needs L01-T1 first (its case 'diffuse' fails)") == 0);
    }
}

TEST_CASE("diagnosis: a TODO's starter code is found in the starter and not in the solution, in every lab", "[unit]") {
    const std::filesystem::path kit = GSV_SOURCE_ROOT;
    int todos = 0;
    for (const std::string& lab : test::all_labs()) {
        const KnownMistakes known = known_mistakes(kit, lab);
        for (const KnownMistake& m : known.mistakes) {
            if (!m.not_started) continue;
            ++todos;
            INFO(lab << " " << m.todo);
            CHECK(still_starter(kit, known.lab_dir, kit / "labs" / known.lab_dir, m.todo, m.files));
            CHECK_FALSE(still_starter(kit, known.lab_dir, kit / "solutions" / known.lab_dir, m.todo, m.files));
        }
    }
    CHECK(todos >= 25);
}

TEST_CASE("diagnosis: two mistakes in two TODOs, neither explaining half alone, are named both where they fit every failure", "[unit]") {
    // "t1" changes every lit case, "t5" only the two it fails: where both touch a case, neither's picture alone is the
    // student's; on the cases only one touches, its picture is.
    const std::vector<KnownMistake> mistakes{mistake("t1", "L01-T1"), mistake("t5", "L01-T5"), mistake("t1 twin", "L01-T1"),
                                             mistake("t3", "L01-T3")};
    const std::vector<std::string> failing{"a", "b", "c", "d", "e"};
    std::vector<std::set<std::string>> explains{{"a", "b"}, {"e"}, {"a", "b"}, {}};
    const std::vector<std::set<std::string>> fails{{"a", "b", "c", "d"}, {"c", "d", "e"}, {"a", "b", "c", "d"}, {"c"}};
    const LabDiagnosis d = name_mistakes_and_pairs("lab01", failing, mistakes, explains, fails);
    REQUIRE(d.found.size() == 2);
    CHECK(d.found[0].names == std::vector<std::string>{"t1", "t1 twin"});
    CHECK(d.found[0].cases == std::vector<std::string>{"a", "b"});
    CHECK(d.found[1].names == std::vector<std::string>{"t5"});
    CHECK(d.found[1].cases == std::vector<std::string>{"e", "c", "d"});
    CHECK(d.found[1].with_earlier);
    CHECK(d.unexplained.empty());
    SECTION("a failure neither fails is not explained by the pair: no pair is named") {
        std::vector<std::string> more = failing;
        more.push_back("f");
        const LabDiagnosis none = name_mistakes_and_pairs("lab01", more, mistakes, explains, fails);
        CHECK(none.found.empty());
        CHECK(none.unexplained == more);
    }
    SECTION("two in the same TODO are not a pair") {
        const std::vector<KnownMistake> same{mistake("t1", "L01-T1"), mistake("t1 other", "L01-T1"), mistake("t1 twin", "L01-T1"),
                                             mistake("t1 third", "L01-T1")};
        CHECK(name_mistakes_and_pairs("lab01", failing, same, explains, fails).found.empty());
    }
}

TEST_CASE("diagnosis: a second mistake whose cases the first also fails is named only where it alone fits", "[unit]") {
    // "t1" explains 9 of 11 by its picture; the two left it fails too, and so does "t5" alone among the mistakes that
    // fail nothing the student passed.
    std::vector<std::string> failing{"c1", "c2", "c3", "c4", "c5", "c6", "c7", "c8", "c9", "renormalize", "stretched"};
    std::set<std::string> nine(failing.begin(), failing.begin() + 9);
    std::set<std::string> all(failing.begin(), failing.end());
    std::vector<KnownMistake> mistakes{mistake("t1", "L01-T1"), mistake("t5", "L01-T5"), mistake("t2", "L01-T2")};
    std::vector<std::set<std::string>> explains{nine, {}, {}};
    std::vector<std::set<std::string>> fails{all, {"renormalize", "stretched"}, {"renormalize", "passed-case"}};
    LabDiagnosis d = name_mistakes_and_pairs("lab01", failing, mistakes, explains, fails);
    REQUIRE(d.found.size() == 2);
    CHECK(d.found[1].names == std::vector<std::string>{"t5"});
    CHECK(d.found[1].cases == std::vector<std::string>{"renormalize", "stretched"});
    CHECK(d.unexplained.empty());
    SECTION("two in different TODOs that fit alike: neither is named") {
        mistakes.push_back(mistake("t3", "L01-T3"));
        explains.push_back({});
        fails.push_back({"renormalize", "stretched"});
        d = name_mistakes_and_pairs("lab01", failing, mistakes, explains, fails);
        REQUIRE(d.found.size() == 1);
        CHECK(d.unexplained == std::vector<std::string>{"renormalize", "stretched"});
    }
}

TEST_CASE("diagnosis: where pictures drawn together can be told, a second mistake under the first is named on that evidence only", "[unit]") {
    // Every failure is the first's by its picture; on "b" the student's picture is the two's together and shows the
    // second beyond the first alone.
    const std::vector<KnownMistake> mistakes{mistake("slopes", "L04-T1"), mistake("hard steps", "L04-T3"), mistake("snow", "L04-T3")};
    const std::vector<std::string> failing{"a", "b", "c"};
    const std::vector<std::set<std::string>> explains{{"a", "b", "c"}, {}, {}};
    const std::vector<std::set<std::string>> fails{{"a", "b", "c"}, {"b"}, {"b", "c"}};
    const auto check = [](bool shows) {
        return TogetherCheck([shows](std::size_t, std::size_t second, const std::string& c) {
            TogetherEvidence e;
            e.matches = second == 1 && c == "b";
            e.shows_second = shows && e.matches;
            return e;
        });
    };
    const LabDiagnosis with = name_mistakes_and_pairs("lab04", failing, mistakes, explains, fails, check(true));
    REQUIRE(with.found.size() == 2);
    CHECK(with.found[0].cases == std::vector<std::string>{"a", "c"});
    CHECK(with.found[1].names == std::vector<std::string>{"hard steps"});
    CHECK(with.found[1].cases == std::vector<std::string>{"b"});
    // The student's picture is the first's alone as near: no second.
    CHECK(name_mistakes_and_pairs("lab04", failing, mistakes, explains, fails, check(false)).found.size() == 1);
    // Without a way to tell pictures drawn together: the first only.
    CHECK(name_mistakes_and_pairs("lab04", failing, mistakes, explains, fails).found.size() == 1);
}
