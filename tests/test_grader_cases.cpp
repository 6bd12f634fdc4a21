// Case files: hidden cases drawn from a seed, and what a broken case file or a missing lab tells.
#include "catch.hpp"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "grader/cases.h"
#include "grader/draw.h"
#include "grader/grade.h"

#include <fstream>
#include <set>

using namespace gsv;

namespace {

std::vector<std::string> settings_of(const LabCases& lab, const std::string& name) {
    for (const auto& c : lab.cases)
        if (c.name == name) return c.settings;
    return {};
}

LabCases with_hidden(std::uint64_t seed) {
    LabCases lab = load_lab_cases(test::source_root() / "grader" / "cases" / "lab01.json");
    add_hidden_cases(lab, hidden_case_file(test::source_root(), "lab01"), seed);
    return lab;
}

}  // namespace

TEST_CASE("draw: the same seed draws the same values everywhere, another seed others", "[grader][cases]") {
    SeededDraw a(42, "lab01/x"), b(42, "lab01/x"), c(43, "lab01/x"), d(42, "lab01/y");
    const auto first = a.next();
    CHECK(first == b.next());
    CHECK(first != c.next());
    CHECK(first != d.next());
    // splitmix64's first output for state 0 is published: 0xe220a8397b1dcdaf.
    // The empty stream's FNV-1a offset basis is folded in, so undo it to reach state 0.
    SeededDraw from_zero(14695981039346656037ull, "");
    CHECK(from_zero.next() == 0xe220a8397b1dcdafull);
    for (int i = 0; i < 1000; ++i) {
        const double u = a.uniform(-2, 3);
        CHECK((u >= -2 && u < 3));
        const long k = a.integer(1, 3);
        CHECK((k >= 1 && k <= 3));
    }
}

TEST_CASE("draw: hidden cases expand, take their seed, and stay in range", "[grader][cases]") {
    const LabCases one = with_hidden(1), same = with_hidden(1), other = with_hidden(2);
    const std::size_t public_cases = load_lab_cases(test::source_root() / "grader" / "cases" / "lab01.json").cases.size();
    REQUIRE(one.cases.size() > public_cases);
    CHECK(settings_of(one, "hidden-phong-1") == settings_of(same, "hidden-phong-1"));
    CHECK(settings_of(one, "hidden-phong-1") != settings_of(other, "hidden-phong-1"));
    CHECK(settings_of(one, "hidden-phong-1") != settings_of(one, "hidden-phong-2"));
    std::set<std::string> names;
    for (const auto& c : one.cases) {
        CHECK(names.insert(c.name).second);
        if (c.name.rfind("hidden-", 0) == 0) CHECK(c.visibility == "hidden");
    }
    const Json spec = parse_json(R"({"x": {"range": [2, 2.5]}, "n": {"int": [3, 3]}, "m": {"choice": ["a"]},
                                     "v": {"vec3": [[0, 0], [1, 1], [-1, -1]]}})", "spec");
    SeededDraw draw(9, "s");
    CHECK(draw_settings(spec, draw)[1] == "n=3");
    CHECK(draw_settings(spec, draw)[2] == "m=a");
    CHECK(draw_settings(spec, draw)[3] == "v=0,1,-1");
}

TEST_CASE("cases: a malformed spec or case file names the file and what is wrong", "[grader][cases]") {
    SeededDraw draw(1, "");
    CHECK(test::gsv_error_message([&] { draw_settings(parse_json(R"({"x": {"range": [3, 1]}})", "h.json"), draw); })
              .find("x.range needs [low, high]") != std::string::npos);
    CHECK(test::gsv_error_message([&] { draw_settings(parse_json(R"({"x": {"gauss": [0, 1]}})", "h.json"), draw); })
              .find("'x' needs one of range, int, choice, vec3") != std::string::npos);
    test::TempDir dir;
    const auto bad = dir.write("grader/cases/lab01.json", "{\"lab\": \"lab01\", \"size\": \"256x256\",\n  \"cases\": [,]}");
    const std::string message = test::gsv_error_message([&] { load_lab_cases(bad); });
    CHECK(message.find("lab01.json:2:") != std::string::npos);
    const auto bad_size = dir.write("b.json", R"({"lab": "lab01", "size": "big", "tolerance": {}, "cases": []})");
    CHECK(test::gsv_error_message([&] { load_lab_cases(bad_size); }).find("WIDTHxHEIGHT") != std::string::npos);
    const auto bad_todo = dir.write("c.json", R"({"lab": "lab01", "size": "8x8", "tolerance": {"live": {"max_channel_diff": 2, "max_differing_fraction": 0},
        "golden": {"max_channel_diff": 2, "max_differing_fraction": 0}}, "cases": [{"name": "a", "todo": "T1", "settings": []}]})");
    CHECK(test::gsv_error_message([&] { load_lab_cases(bad_todo); }).find("expected an id like L01-T2") != std::string::npos);

    // Through grade(): a broken case file and a lab with no cases stop the run with one clear line.
    GradeOptions options;
    options.kit_root = dir.path();
    options.bin_dir = dir.path("bin");
    options.out_dir = dir.path("out");
    CHECK(test::gsv_error_message([&] { grade(options); }).find("lab01.json:2:") != std::string::npos);
    options.kit_root = test::source_root();
    options.labs = {"lab99"};
    CHECK(test::gsv_error_message([&] { grade(options); }).find("no grading cases for lab 'lab99'") != std::string::npos);
    options.labs = {"lab01"};
    options.submission = dir.path("nothing-here");
    CHECK(test::gsv_error_message([&] { grade(options); }).find("has no labs/ folder") != std::string::npos);
}

TEST_CASE("cases: a truncated golden image is the reference's failure, named, not a crash", "[grader][cases]") {
    test::TempDir dir;
    std::filesystem::create_directories(dir.path("kit/grader"));
    std::filesystem::copy(test::source_root() / "grader" / "cases", dir.path("kit/grader/cases"));
    std::filesystem::copy(test::source_root() / "grader" / "golden", dir.path("kit/grader/golden"),
                          std::filesystem::copy_options::recursive);
    const auto golden = dir.path("kit/grader/golden/lab01/gooch.png");
    const std::string bytes = test::read_text(golden);
    std::ofstream(golden, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 3);
    GradeOptions options;
    options.kit_root = dir.path("kit");
    options.bin_dir = test::bin_dir();
    options.out_dir = dir.path("out");
    options.self_check = true;
    const GradeReport report = grade(options);
    bool seen = false;
    for (const auto& r : report.results)
        if (r.name == "gooch") {
            seen = true;
            CHECK(r.status == CaseStatus::ReferenceFailed);
            CHECK(r.detail.find("gooch.png") != std::string::npos);
        }
    CHECK(seen);
    CHECK(report.mode == "self-check");
}
