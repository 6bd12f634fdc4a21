// Held-out mistakes (issue 40): mistakes students make that the kit's lists (tests/mutants/) do not hold, kept in
// tests/heldout/<lab>.json, out of the lists and their texts. Graded as a student's submission, each must lose points
// and must not be given a known mistake's name: the diagnosis says "no known mistake matches" rather than the nearest.
// Wrong names at most 1 in 20.
#include "grader_fixture.h"

#include "common/app/kit_layout.h"

using namespace gsv;

namespace {

void held_out(const std::string& lab) {
    const Json list = read_json_file(test::source_root() / "tests" / "heldout" / (lab + ".json"));
    const std::string lab_dir = test::mutant_spec(lab).string_at("lab_dir");
    const auto cache = std::make_shared<ReferenceCache>();
    int mistakes = 0, wrong = 0, unexplained = 0;
    std::string outcomes;
    for (const Json& m : list.array_at("mistakes").as_array()) {
        test::EditedKit kit(lab, lab_dir, m);
        GradeOptions options = kit.options();
        options.hidden = false;
        options.timing = false;
        options.reference_cache = cache;
        const GradeReport report = grade(options);
        bool lost = false;
        for (const auto& r : report.results) lost = lost || r.points < r.max_points;
        INFO(lab << ": held-out '" << m.string_at("name") << "' loses no points: it is not a mistake the cases see");
        CHECK(lost);
        ++mistakes;
        std::string named;
        for (const auto& d : report.diagnoses)
            for (const auto& f : d.found) named += (named.empty() ? "" : "; ") + f.names.front();
        if (!named.empty()) ++wrong;
        bool said_unexplained = false;
        for (const auto& d : report.diagnoses) said_unexplained = said_unexplained || !d.unexplained.empty();
        unexplained += said_unexplained;
        outcomes += "  '" + m.string_at("name") + "': " + (named.empty() ? std::string("no known mistake") : "named '" + named + "'") + "\n";
    }
    INFO(lab << ": " << wrong << " of " << mistakes << " held-out mistakes given a known mistake's name:\n" << outcomes);
    CHECK(mistakes >= 3);
    CHECK(wrong * 20 <= mistakes);
    WARN(lab << " held out: " << mistakes << " mistakes, " << wrong << " named wrong, " << unexplained
              << " said 'no known mistake matches'\n" << outcomes);
}

}  // namespace

TEST_CASE("lab01: held-out mistakes get no known mistake's name", "[grader][mutants]") { held_out("lab01"); }
TEST_CASE("lab02: held-out mistakes get no known mistake's name", "[grader][mutants]") { held_out("lab02"); }
TEST_CASE("lab03: held-out mistakes get no known mistake's name", "[grader][mutants]") { held_out("lab03"); }
TEST_CASE("lab04: held-out mistakes get no known mistake's name", "[grader][mutants]") { held_out("lab04"); }
TEST_CASE("lab05: held-out mistakes get no known mistake's name", "[grader][mutants][gl43]") { held_out("lab05"); }
TEST_CASE("lab06: held-out mistakes get no known mistake's name", "[grader][mutants]") { held_out("lab06"); }
TEST_CASE("lab07: held-out mistakes get no known mistake's name", "[grader][mutants]") { held_out("lab07"); }
