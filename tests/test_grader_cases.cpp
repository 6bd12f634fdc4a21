// Case files: hidden cases drawn from a seed, and what a broken case file or a missing lab tells.
#include "catch.hpp"
#include "gl_fixture.h"
#include "lab_runner.h"
#include "test_support.h"

#include "grader/src/cases/cases.h"
#include "grader/src/cases/draw.h"
#include "grader/src/grade/grade.h"

#include <algorithm>
#include <fstream>
#include <set>

using namespace gsv;
namespace fs = std::filesystem;

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

TEST_CASE("draw: a whole number drawn in steps keeps off the values between them", "[grader][cases]") {
    const Json spec = parse_json(R"({"odd": {"int": [1, 99], "step": 2}, "tens": {"int": [10, 55], "step": 10}})", "spec");
    std::set<std::string> seen;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        SeededDraw draw(seed, "s");
        const auto settings = draw_settings(spec, draw);
        const long odd = std::stol(settings[0].substr(4)), tens = std::stol(settings[1].substr(5));
        CHECK(odd % 2 == 1);
        CHECK(odd >= 1);
        CHECK(odd <= 99);
        CHECK(tens % 10 == 0);
        CHECK(tens >= 10);
        CHECK(tens <= 50);
        seen.insert(settings[1]);
    }
    CHECK(seen.size() == 5);  // 10, 20, 30, 40, 50: every step is drawn
    const Json bad = parse_json(R"({"n": {"int": [1, 9], "step": 0.5}})", "spec");
    SeededDraw draw(1, "s");
    CHECK(test::gsv_error_message([&] { draw_settings(bad, draw); }).find("n.step needs a whole number >= 1") != std::string::npos);
}

TEST_CASE("cases: a draw that holds only where another setting has a value is kept only there", "[grader][cases]") {
    const Json spec = parse_json(R"({"field": {"choice": ["rotation", "double_gyre"]},
                                     "time": {"range": [0, 10], "when": "field=double_gyre|file"}, "n": {"int": [1, 1000]}})",
                                 "spec");
    int kept = 0, dropped = 0;
    for (int seed = 1; seed <= 40; ++seed) {
        SeededDraw draw(static_cast<std::uint64_t>(seed), "s");
        const auto settings = draw_settings(spec, draw);
        const bool gyre = settings.front() == "field=double_gyre";
        const bool has_time = std::any_of(settings.begin(), settings.end(), [](const std::string& s) { return s.rfind("time=", 0) == 0; });
        CHECK(has_time == gyre);
        (gyre ? kept : dropped) += 1;
        // Drawn all the same: what follows does not depend on whether it was kept.
        SeededDraw again(static_cast<std::uint64_t>(seed), "s");
        const auto fixed = draw_settings(parse_json(R"({"field": {"choice": ["rotation", "double_gyre"]},
                                                       "time": {"range": [0, 10]}, "n": {"int": [1, 1000]}})", "spec"),
                                         again);
        CHECK(settings.back() == fixed.back());
    }
    CHECK(kept > 0);
    CHECK(dropped > 0);
    // The condition may name one of the case's own settings; a parameter neither set nor drawn is a mistake.
    SeededDraw draw(3, "s");
    const Json on_fixed = parse_json(R"({"iso_value": {"range": [0.3, 0.7], "when": "compositing=iso"}})", "spec");
    CHECK(draw_settings(on_fixed, draw, {"compositing=iso"}).size() == 1);
    CHECK(draw_settings(on_fixed, draw, {"compositing=dvr"}).empty());
    CHECK(test::gsv_error_message([&] { draw_settings(on_fixed, draw); }).find("a parameter the case sets or draws") !=
          std::string::npos);
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
    // A case's "es" is an OpenGL ES version: 3.0 to 3.2, read as one, or the file and case are named.
    const std::string tolerance = R"("tolerance": {"live": {"max_channel_diff": 2, "max_differing_fraction": 0},
        "golden": {"max_channel_diff": 2, "max_differing_fraction": 0}})";
    const auto es_case = [&](const std::string& name, const std::string& es) {
        return dir.write(name, R"({"lab": "lab01", "size": "8x8", )" + tolerance +
                                   R"(, "cases": [{"name": "a", "todo": "L01-T1", "settings": [], "es": ")" + es + R"("}]})");
    };
    CHECK(load_lab_cases(es_case("es-ok.json", "3.2")).cases.at(0).es_version == GlVersion{3, 2});
    CHECK(test::gsv_error_message([&] { load_lab_cases(es_case("es-desktop.json", "4.1")); })
              .find("es-desktop.json: case 'a': \"es\": GL version '4.1' is out of range [3.0, 3.2] for the es profile") !=
          std::string::npos);
    // A case's "feature" is a row of common/gl/gl_features.h by its key: compute lifts the case to ES 3.1, as "es" does;
    // an unknown one names the file, the case and the value.
    const auto feature_case = [&](const std::string& name, const std::string& feature) {
        return dir.write(name, R"({"lab": "lab01", "size": "8x8", )" + tolerance +
                                   R"(, "cases": [{"name": "a", "todo": "L01-T1", "settings": [], "feature": ")" + feature + R"("}]})");
    };
    const GradeCase compute = load_lab_cases(feature_case("feature-ok.json", "compute")).cases.at(0);
    CHECK(compute.feature == &gl_feature::kCompute);
    CHECK(compute.es_version == GlVersion{3, 1});
    CHECK(test::gsv_error_message([&] { load_lab_cases(feature_case("feature-bad.json", "raytracing")); })
              .find("feature-bad.json: case 'a': \"feature\": 'raytracing' is no feature the kit knows") != std::string::npos);
    // The page's opening case must be one of the file's cases.
    const auto page_case = dir.write("page.json", R"({"lab": "lab01", "size": "8x8", "page_case": "b", )" + tolerance +
                                                      R"(, "cases": [{"name": "a", "todo": "L01-T1", "settings": []}]})");
    CHECK(test::gsv_error_message([&] { load_lab_cases(page_case); })
              .find("page.json: \"page_case\" is 'b', which is not one of its cases") != std::string::npos);

    // Through grade(): a broken case file and a lab with no cases stop the run with one clear line.
    GradeOptions options;
    options.diagnose = DiagnoseCases::Off;  // the diagnosis has tests of its own (test_grader_diagnosis*.cpp)
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
    options.diagnose = DiagnoseCases::Off;  // the diagnosis has tests of its own (test_grader_diagnosis*.cpp)
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

TEST_CASE("cases: the arrays tolerance and a case's arrays are read, bad values refused naming the file", "[grader][cases]") {
    test::TempDir dir;
    const std::string images = R"("live": {"max_channel_diff": 2, "max_differing_fraction": 0.001},
        "golden": {"max_channel_diff": 24, "max_differing_fraction": 0.01})";
    auto file = [&](const std::string& tolerance_extra, const std::string& case_extra) {
        return dir.write("grader/cases/lab05.json", R"({"lab": "lab05", "size": "8x8", "tolerance": {)" + images +
                                                        tolerance_extra + R"(}, "cases": [
            {"name": "abc", "todo": "L05-T3", "settings": []},
            {"name": "ragged", "todo": "L05-T2", "settings": [])" + case_extra + "}]}");
    };
    auto error = [&](const std::string& tolerance_extra, const std::string& case_extra) {
        const auto path = file(tolerance_extra, case_extra);
        const std::string m = test::gsv_error_message([&] { load_lab_cases(path); });
        CHECK(m.find("lab05.json") != std::string::npos);
        CHECK(m.find('\n') == std::string::npos);
        return m;
    };

    // Labs 01-04: no arrays tolerance, nothing about arrays checked.
    const LabCases plain = load_lab_cases(file("", ""));
    CHECK_FALSE(plain.checks_arrays());
    CHECK_FALSE(plain.cases[1].arrays.has_value());
    for (const char* lab : {"lab01", "lab02", "lab03", "lab04"})
        CHECK_FALSE(load_lab_cases(test::source_root() / "grader" / "cases" / (std::string(lab) + ".json")).checks_arrays());

    const LabCases one = load_lab_cases(file(R"(, "arrays": {"max_abs": 1e-4, "max_differing_fraction": 0.001})",
                                             R"(, "arrays": ["positions"])"));
    REQUIRE(one.checks_arrays());
    CHECK(one.live_array_tolerance->max_abs == 1e-4);
    CHECK(one.live_array_tolerance->max_differing_fraction == 0.001);
    CHECK(one.golden_array_tolerance->max_abs == 1e-4);  // one tolerance for both
    CHECK_FALSE(one.cases[0].arrays.has_value());          // every array the reference hands in
    CHECK(*one.cases[1].arrays == std::vector<std::string>{"positions"});

    const LabCases two = load_lab_cases(file(R"(, "arrays": {"max_abs": 0, "max_differing_fraction": 0},
        "arrays_golden": {"max_abs": 0.01, "max_differing_fraction": 0.02})", R"(, "arrays": [])"));
    CHECK(two.live_array_tolerance->max_abs == 0);
    CHECK(two.golden_array_tolerance->max_abs == 0.01);
    CHECK(two.golden_array_tolerance->max_differing_fraction == 0.02);
    CHECK(two.cases[1].arrays->empty());  // checks none

    const std::string ok = R"(, "arrays": {"max_abs": 1e-4, "max_differing_fraction": 0.001})";
    CHECK(error(R"(, "arrays": {"max_abs": -1, "max_differing_fraction": 0})", "").find("tolerance.arrays out of range") != std::string::npos);
    CHECK(error(R"(, "arrays": {"max_abs": 1, "max_differing_fraction": 1.5})", "").find("max_differing_fraction 0..1") != std::string::npos);
    CHECK(error(R"(, "arrays": {"max_abs": 1})", "").find("max_differing_fraction") != std::string::npos);
    CHECK(error(R"(, "arrays": {"max_abs": "small", "max_differing_fraction": 0})", "").find("max_abs") != std::string::npos);
    CHECK(error(ok + R"(, "arrays_golden": {"max_abs": -0.5, "max_differing_fraction": 0})", "")
              .find("tolerance.arrays_golden out of range") != std::string::npos);
    CHECK(error(R"(, "arrays_golden": {"max_abs": 1, "max_differing_fraction": 0})", "").find("'arrays_golden' but no 'arrays'") != std::string::npos);
    CHECK(error("", R"(, "arrays": ["positions"])").find("case 'ragged' lists arrays, but the tolerance has no 'arrays'") != std::string::npos);
    CHECK(error(ok, R"(, "arrays": ["Positions"])").find("case 'ragged' lists array 'Positions'") != std::string::npos);
    CHECK(error(ok, R"(, "arrays": ["positions", "positions"])").find("lists array 'positions' twice") != std::string::npos);
    CHECK(error(ok, R"(, "arrays": "positions")").find("cases[1].arrays") != std::string::npos);
    CHECK(error(ok, R"(, "arrays": [3])").find("cases[1].arrays[0]") != std::string::npos);

    // Hidden cases are held to the same rules.
    LabCases lab = load_lab_cases(file("", ""));
    const auto hidden = dir.write("grader/hidden/lab05.json", R"({"lab": "lab05", "cases": [
        {"name": "h", "todo": "L05-T3", "settings": [], "draw": {}, "arrays": ["positions"]}]})");
    CHECK(test::gsv_error_message([&] { add_hidden_cases(lab, hidden, 1); }).find("hidden/lab05.json: case 'h' lists arrays") != std::string::npos);
}

TEST_CASE("cases: an instructor's mistake stops grading in one line before any student code runs", "[grader]") {
    test::TempDir dir;
    const auto kit = dir.path("kit");
    fs::create_directories(kit / "grader" / "cases");
    fs::create_directories(kit / "solutions");
    fs::create_directory_symlink(test::source_root() / "solutions" / "lab02_lic", kit / "solutions" / "lab02_lic");
    fs::create_directory_symlink(test::source_root() / "shaders", kit / "shaders");
    fs::create_directory_symlink(test::source_root() / "data", kit / "data");
    const std::string original = test::read_text(test::source_root() / "grader" / "cases" / "lab02.json");
    GradeOptions options;
    options.diagnose = DiagnoseCases::Off;  // the diagnosis has tests of its own (test_grader_diagnosis*.cpp)
    options.kit_root = kit;
    options.bin_dir = test::bin_dir();
    options.out_dir = dir.path("out");
    options.labs = {"lab02"};
    options.timing = false;
    options.allow_readable_kit = true;
    const auto with = [&](const std::string& from, const std::string& to) {
        std::string text = original;
        REQUIRE(text.find(from) != std::string::npos);
        text.replace(text.find(from), from.size(), to);
        std::ofstream(kit / "grader" / "cases" / "lab02.json") << text;
    };
    with("\"length=120\"", "\"lenght=120\"");
    std::string message = test::gsv_error_message([&] { grade(options); });
    CHECK(message.find("lab02.json:") != std::string::npos);
    CHECK(message.find("case 'long': unknown parameter 'lenght'") != std::string::npos);
    with("\"length=120\"", "\"length=9999\"");
    message = test::gsv_error_message([&] { grade(options); });
    CHECK(message.find("case 'long'") != std::string::npos);
    CHECK(message.find("9999") != std::string::npos);
    with("\"todo\": \"L02-T5\"", "\"todo\": \"L02-T9\"");
    message = test::gsv_error_message([&] { grade(options); });
    CHECK(message.find("case 'midpoint': no lab has a TODO 'L02-T9'") != std::string::npos);
    // A hidden case as drawn: its settings go through the reference's parameters too.
    with("\"length=120\"", "\"length=120\"");
    fs::create_directories(kit / "grader" / "hidden");
    std::ofstream(kit / "grader" / "hidden" / "lab02.json")
        << R"({"lab": "lab02", "cases": [{"name": "far", "todo": "L02-T1", "settings": ["length=500"], "draw": {}}]})";
    message = test::gsv_error_message([&] { grade(options); });
    CHECK(message.find("hidden/lab02.json: case 'far' (as drawn): ") != std::string::npos);
    CHECK(message.find("500") != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
}

TEST_CASE("cases: a reference that fails to render ends grading with status 3 (the kit's fault), never a zero for the student", "[grader]") {
    test::TempDir dir;
    dir.write("kit/grader/cases/lab99.json", R"({"lab": "lab99", "size": "4x4", "timeout_s": 20,
        "tolerance": {"live": {"max_channel_diff": 0, "max_differing_fraction": 0},
                      "golden": {"max_channel_diff": 0, "max_differing_fraction": 0}},
        "cases": [{"name": "only", "todo": "L99-T1", "points": 1, "settings": []}]})");
    Image image(4, 4);
    write_png(dir.path("picture.png"), image);
    // The student's lab draws; the reference fails at render time (its `list` is fine).
    const auto script = [&](const std::string& name, const std::string& body) {
        const auto path = dir.write("bin/" + name, "#!/bin/sh\n" + body);
        fs::permissions(path, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    };
    script("lab99", "out=\nwhile [ $# -gt 0 ]; do case \"$1\" in --out) out=$2; shift;; esac; shift; done\n"
                    "printf ff >&3\ncp '" + dir.path("picture.png").string() + "' \"$out\"\necho '{}' > \"${out%.png}.json\"\n");
    script("lab99_solution", "[ \"$1\" = list ] && exit 0\necho 'lab99: the reference broke' >&2\nexit 1\n");
    ProcessLimits limits;
    limits.timeout = std::chrono::seconds(60);
    const ProcessResult graded = run_process({(test::bin_dir() / "gsv-grade").string(), "--kit", dir.path("kit").string(), "--bin",
                                              dir.path("bin").string(), "--out", dir.path("out").string(), "--no-timing",
                                              "--allow-readable-kit", "--no-sandbox"},
                                             dir.path(), limits);
    INFO(graded.output);
    CHECK(graded.exit_code == 3);
    CHECK(graded.output.find("the kit's fault, not the student's, on 1 checks (marked 'reference failed'") != std::string::npos);
    CHECK(graded.output.find("reference failed") != std::string::npos);
}

TEST_CASE("cases: a tolerance's neighbourhood is read per lab and per case, a bad one refused naming the file and value", "[grader][cases]") {
    test::TempDir dir;
    auto file = [&](const std::string& golden_extra, const std::string& case_tolerance) {
        return dir.write("grader/cases/lab05.json", R"({"lab": "lab05", "size": "8x8", "tolerance": {
            "live": {"max_channel_diff": 2, "max_differing_fraction": 0.001},
            "golden": {"max_channel_diff": 24, "max_differing_fraction": 0.01)" + golden_extra + R"(}},
            "cases": [{"name": "abc", "todo": "L05-T3", "settings": []},
                      {"name": "ragged", "todo": "L05-T2", "settings": [])" + case_tolerance + "}]}");
    };
    // None given: 0, each pixel at its own place, as every lab but 05 has it.
    const LabCases plain = load_lab_cases(file("", ""));
    CHECK(plain.golden_tolerance.neighbourhood == 0);
    CHECK(plain.live_tolerance.neighbourhood == 0);
    for (const std::string& lab : test::all_labs()) {
        const LabCases shipped = load_lab_cases(test::source_root() / "grader" / "cases" / (lab + ".json"));
        if (shipped.arrays_are == "particles") continue;  // lab 05's, below
        INFO(lab);
        CHECK(shipped.golden_tolerance.neighbourhood == 0);
        for (const auto& c : shipped.cases) CHECK(shipped.tolerance(c, false).neighbourhood == 0);
    }
    // Lab 05's particles are matched within two pixels against the goldens, never live (same machine, same placement).
    const LabCases lab05 = load_lab_cases(test::source_root() / "grader" / "cases" / "lab05.json");
    CHECK(lab05.golden_tolerance.neighbourhood == 2);
    CHECK(lab05.live_tolerance.neighbourhood == 0);
    CHECK(lab05.arrays_are == "particles");

    const LabCases per_lab = load_lab_cases(file(R"(, "neighbourhood": 1)", ""));
    CHECK(per_lab.golden_tolerance.neighbourhood == 1);
    CHECK(per_lab.tolerance(per_lab.cases[1], false).neighbourhood == 1);
    CHECK(per_lab.tolerance(per_lab.cases[1], true).neighbourhood == 0);
    const LabCases per_case = load_lab_cases(file("", R"(, "tolerance": {"golden": {"max_channel_diff": 24, "max_differing_fraction": 0.02, "neighbourhood": 2}})"));
    CHECK(per_case.tolerance(per_case.cases[0], false).neighbourhood == 0);
    CHECK(per_case.tolerance(per_case.cases[1], false).neighbourhood == 2);

    for (const std::string bad : {"1.5", "-1", "4", "\"one\"", "true"}) {
        INFO(bad);
        const auto path = file(R"(, "neighbourhood": )" + bad, "");
        const std::string m = test::gsv_error_message([&] { load_lab_cases(path); });
        CHECK(m.find("lab05.json:3: tolerance.golden.neighbourhood is " + bad + "; a neighbourhood is a whole number of pixels 0..3") !=
              std::string::npos);
        CHECK(m.find('\n') == std::string::npos);
    }
    const auto in_case = file("", R"(, "tolerance": {"golden": {"max_channel_diff": 24, "max_differing_fraction": 0.02, "neighbourhood": 0.5}})");
    CHECK(test::gsv_error_message([&] { load_lab_cases(in_case); }).find("cases[1].tolerance.golden.neighbourhood is 0.5") != std::string::npos);
}
