// The grader's reports, written from a hand-built GradeReport: each must parse as what it claims to
// be, keep hidden checks hidden, and carry student output (which may hold anything) safely escaped.
#include "catch.hpp"
#include "test_support.h"

#include "common/core/error.h"
#include "common/image/image.h"
#include "common/io/json.h"
#include "grader/src/core/grade_result.h"
#include "grader/src/report/report.h"
#include "grader/src/report/report_format.h"

#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <sstream>
#include <string>

using namespace gsv;
namespace fs = std::filesystem;

namespace {

const std::string kHostileOutput = "line 1\n<script>alert(1)</script> & \"quotes\" 'single'\x01 end\xff\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::size_t count(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
    return n;
}

Image solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = image.at(x, y);
            p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
        }
    return image;
}

CaseResult make_case(const std::string& lab, const std::string& name, const std::string& todo, double points,
                     double max_points, CaseStatus status) {
    CaseResult r;
    r.lab = lab;
    r.name = name;
    r.todo = todo;
    r.points = points;
    r.max_points = max_points;
    r.status = status;
    r.reference = "live";
    r.seconds = 0.25;
    return r;
}

// Five checks over two labs, images written under out_dir: score 5 of 19.
GradeReport sample_report(const fs::path& out_dir) {
    GradeReport report;
    report.submission = "/submissions/alice";
    report.mode = "instructor";
    report.seed = 12345678901234567890ull;  // above 2^53: a double would change it
    report.hidden_included = true;
    report.timing_included = true;
    report.sandbox = "user namespaces, no network";
    report.seconds = 12.5;
    report.builds.push_back({"lab01", true, "", 3.0});
    report.builds.push_back({"lab02", false, "[1/3] compiling\nlab02/main.cpp:12:5: error: expected ';'\nmore", 1.0});

    CaseResult phong = make_case("lab01", "phong", "L01-T3", 5, 5, CaseStatus::Passed);
    phong.description = "Phong shading of a sphere";
    phong.settings = {"shininess=32"};
    phong.detail = "max diff 1, 0 of 4 px differ (0.00%), PSNR inf dB, SSIM 1.000";
    phong.image.done = true;
    phong.image.tolerance = {2, 0.001};
    phong.image.total_pixels = 4;
    phong.image.psnr = std::numeric_limits<double>::infinity();
    phong.image.ssim = 1.0;
    phong.actual_png = "lab01/phong/actual.png";
    phong.expected_png = "lab01/phong/expected.png";

    CaseResult shadow = make_case("lab01", "shadow", "L01-T4", 0, 5, CaseStatus::WrongImage);
    shadow.visibility = "hidden";
    shadow.detail = "max diff 200, 3 of 4 px differ (75.00%) " + std::string(200, 'x');
    shadow.output = kHostileOutput;
    shadow.image.done = true;
    shadow.image.tolerance = {2, 0.001};
    shadow.image.max_channel_diff = 200;
    shadow.image.differing_pixels = 3;
    shadow.image.total_pixels = 4;
    shadow.image.psnr = 9.5;
    shadow.image.ssim = 0.25;
    shadow.image.diff_x0 = 0, shadow.image.diff_y0 = 0, shadow.image.diff_x1 = 1, shadow.image.diff_y1 = 1;
    shadow.actual_png = "lab01/shadow/actual.png";
    shadow.expected_png = "lab01/shadow/expected.png";
    shadow.diff_png = "lab01/shadow/diff.png";  // never written: the report must say so, not throw

    CaseResult slow = make_case("lab01", "phong", "L01-T3", 0, 2, CaseStatus::TooSlow);
    slow.kind = "timing";
    slow.detail = "1.80x the reference (allowed 1.50x)";
    slow.timing = {true, 9.0, 5.0, 1.8, 1.5, 7, true};

    CaseResult build = make_case("lab02", "basic", "L02-T1", 0, 4, CaseStatus::BuildError);
    build.detail = "lab02/main.cpp:12:5: error: expected ';'";
    build.output = report.builds[1].log;
    CaseResult reference = make_case("lab02", "fancy", "L02-T2", 0, 3, CaseStatus::ReferenceFailed);
    reference.detail = "the reference solution failed: crash";

    report.results = {phong, shadow, slow, build, reference};

    write_png(out_dir / phong.actual_png, solid(2, 2, 200, 10, 10));
    write_png(out_dir / phong.expected_png, solid(2, 2, 200, 10, 10));
    write_png(out_dir / shadow.actual_png, solid(2, 2, 0, 0, 0));
    write_png(out_dir / shadow.expected_png, solid(2, 2, 0, 200, 0));
    return report;
}

// Exit status and stdout of a shell command.
std::pair<int, std::string> run(const std::string& command) {
    std::string output;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return {-1, ""};
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    return {pclose(pipe), output};
}

bool have_python3() { return std::system("command -v python3 >/dev/null 2>&1") == 0; }

}  // namespace

TEST_CASE("grader reports: status names are short, distinct and lower case but for NaN and GPU", "[grader]") {
    std::set<std::string> names;
    for (int s = 0; s <= static_cast<int>(CaseStatus::GpuMargin); ++s) names.insert(status_name(CaseStatus(s)));
    CHECK(names.size() == static_cast<std::size_t>(CaseStatus::GpuMargin) + 1);
    CHECK(names.count("unknown") == 0);
    CHECK(std::string(status_name(CaseStatus::GpuMargin)) == "GPU margin");
    CHECK(std::string(status_name(CaseStatus::WrongData)) == "wrong data");
    CHECK(std::string(status_name(CaseStatus::Passed)) == "passed");
    CHECK(std::string(status_name(CaseStatus::ShaderCompileError)) == "shader compile error");
    CHECK(std::string(status_name(CaseStatus::NonFinite)) == "NaN");
    CHECK(std::string(status_name(CaseStatus::TooSlow)) == "too slow");
    CHECK(std::string(status_name(CaseStatus::ReferenceFailed)) == "reference failed");
}

TEST_CASE("grader reports: score and max score sum the checks", "[grader]") {
    test::TempDir dir;
    const GradeReport report = sample_report(dir.path());
    CHECK(report.score() == 5);
    CHECK(report.max_score() == 19);
    CHECK(GradeReport{}.score() == 0);
}

TEST_CASE("grader reports: text helpers", "[grader]") {
    // RFC 4648 test vectors.
    CHECK(base64("") == "");
    CHECK(base64("f") == "Zg==");
    CHECK(base64("fo") == "Zm8=");
    CHECK(base64("foo") == "Zm9v");
    CHECK(base64("foob") == "Zm9vYg==");
    CHECK(base64("foobar") == "Zm9vYmFy");
    CHECK(base64(std::string("\xff\x00\x80", 3)) == "/wCA");
    CHECK(format_points(5) == "5");
    CHECK(format_points(2.5) == "2.5");
    CHECK(format_points(1.0 / 3.0) == "0.33");
    CHECK(valid_utf8("ok \xc3\xa9 \xff \xc0\xaf \xed\xa0\x80") == "ok \xc3\xa9 \xEF\xBF\xBD \xEF\xBF\xBD\xEF\xBF\xBD "
                                                                  "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");
    CHECK(xml_safe_text("a\x01\x1b[31m\tb\n\xef\xbf\xbe") == "a[31m\tb\n");
    CHECK(one_line("a\nb\x1b", 10) == "a b");
    CHECK(one_line("\xc3\xa9\xc3\xa9\xc3\xa9", 6) == "\xc3\xa9\xc3\xa9\xc3\xa9");
    CHECK(one_line("\xc3\xa9\xc3\xa9\xc3\xa9", 5) == "\xc3\xa9...");
    CHECK(one_line("a\xc3\xa9\xc3\xa9\xc3\xa9", 5) == "a...");  // cut before, never inside, a character
    CHECK(first_error_line("\n[1/2] cc\nx.cpp:3: Error: bad\n") == "x.cpp:3: Error: bad");
    CHECK(first_error_line("\n  \nwarning only\n") == "warning only");
}

TEST_CASE("grader reports: Gradescope results.json", "[grader]") {
    test::TempDir dir;
    const GradeReport report = sample_report(dir.path());
    const std::string text = gradescope_json(report);
    const Json json = parse_json(text, "results.json");
    CHECK(json.number_at("score") == 5);
    CHECK(json.string_at("output") == "1 of 4 public checks passed; did not build: lab02; some checks could not be "
                                      "graded (the reference failed), tell the course staff.");
    const Json& tests = json.array_at("tests");
    REQUIRE(tests.size() == 5);

    const Json& phong = tests.at(0);
    CHECK(phong.string_at("name") == "lab01/phong (L01-T3)");
    CHECK(phong.number_at("score") == 5);
    CHECK(phong.number_at("max_score") == 5);
    CHECK(phong.string_at("status") == "passed");
    CHECK(phong.string_at("visibility") == "visible");
    REQUIRE(phong.array_at("tags").size() == 1);
    CHECK(phong.array_at("tags").at(0).as_string() == "L01-T3");

    const Json& shadow = tests.at(1);
    CHECK(shadow.string_at("name") == "lab01/shadow (L01-T4)");
    CHECK(shadow.string_at("status") == "failed");
    CHECK(shadow.string_at("visibility") == "after_due_date");
    CHECK(shadow.number_at("max_score") == 5);
    const std::string output = shadow.string_at("output");
    CHECK(output.rfind("wrong image: max diff 200", 0) == 0);
    CHECK(contains(output, "\nline 1\n<script>alert(1)</script> & \"quotes\""));
    CHECK(contains(output, "\x01 end"));  // JSON escapes it as \u0001 and parsing gives it back
    CHECK_FALSE(contains(text, "\xff"));  // invalid UTF-8 never reaches the file

    CHECK(tests.at(2).string_at("name") == "lab01/phong [time] (L01-T3)");
    CHECK(tests.at(2).string_at("status") == "failed");
    CHECK(tests.at(3).string_at("output").rfind("build error: lab02/main.cpp:12:5", 0) == 0);
    CHECK(tests.at(4).string_at("output").rfind("reference failed:", 0) == 0);

    // A misspelt visibility hides the check rather than showing it.
    GradeReport typo = report;
    typo.results[0].visibility = "Hidden";
    const Json typo_json = parse_json(gradescope_json(typo), "results.json");
    CHECK(typo_json.array_at("tests").at(0).string_at("visibility") == "after_due_date");
    CHECK(contains(typo_json.string_at("output"), "0 of 3 public checks passed"));
}

TEST_CASE("grader reports: report.json carries every measurement", "[grader]") {
    test::TempDir dir;
    const GradeReport report = sample_report(dir.path());
    const Json json = parse_json(report_json(report), "report.json");
    CHECK(json.string_at("mode") == "instructor");
    CHECK(json.string_at("profile") == "core");
    GradeReport on_es = report;
    on_es.profile = "es";
    CHECK(parse_json(report_json(on_es), "report.json").string_at("profile") == "es");
    CHECK(contains(score_table(on_es), "profile  es (the labs and the references ran on it)"));
    CHECK(!contains(score_table(report), "profile "));
    CHECK(json.string_at("seed") == "12345678901234567890");
    CHECK(json.string_at("sandbox") == "user namespaces, no network");
    CHECK(json.number_at("seconds") == 12.5);
    CHECK(json.number_at("max_score") == 19);
    REQUIRE(json.array_at("builds").size() == 2);
    CHECK_FALSE(json.array_at("builds").at(1).bool_at("ok"));
    CHECK(contains(json.array_at("builds").at(1).string_at("log"), "expected ';'"));

    const Json& results = json.array_at("results");
    REQUIRE(results.size() == 5);
    const Json& phong = results.at(0);
    CHECK(phong.object_at("image").find("psnr")->is_null());  // +inf: identical
    CHECK(phong.object_at("image").number_at("ssim") == 1.0);
    CHECK(phong.object_at("image").find("diff_box")->is_null());
    CHECK(phong.string_at("actual_png") == "lab01/phong/actual.png");
    CHECK(phong.array_at("settings").at(0).as_string() == "shininess=32");
    CHECK(phong.string_at("description") == "Phong shading of a sphere");

    const Json& shadow = results.at(1);
    CHECK(shadow.string_at("status") == "wrong image");
    CHECK(shadow.string_at("visibility") == "hidden");
    CHECK(shadow.object_at("image").number_at("ssim") == 0.25);
    CHECK(shadow.object_at("image").number_at("psnr") == 9.5);
    CHECK(shadow.object_at("image").int_at("differing_pixels") == 3);
    CHECK(shadow.object_at("image").object_at("tolerance").number_at("max_differing_fraction") == 0.001);
    CHECK(shadow.object_at("image").object_at("tolerance").int_at("neighbourhood") == 0);
    GradeReport matched = report;
    matched.results.at(1).image.tolerance.neighbourhood = 1;
    CHECK(parse_json(report_json(matched), "report.json").array_at("results").at(1).object_at("image").object_at("tolerance").int_at("neighbourhood") == 1);
    CHECK(contains(html_report(matched, dir.path()), "<tr><th>placement</th><td>matched within 1 px (each pixel against the best of its neighbours, both ways)</td></tr>"));
    CHECK(contains(html_report(report, dir.path()), "<tr><th>placement</th><td>each pixel at its own place</td></tr>"));
    CHECK(shadow.object_at("image").object_at("diff_box").int_at("x1") == 1);
    CHECK(shadow.string_at("diff_png") == "lab01/shadow/diff.png");

    const Json& slow = results.at(2);
    CHECK(slow.string_at("kind") == "timing");
    CHECK(slow.object_at("timing").number_at("ratio") == 1.8);
    CHECK(slow.object_at("timing").number_at("max_ratio") == 1.5);
    CHECK(slow.object_at("timing").int_at("rounds") == 7);
    CHECK(slow.object_at("timing").bool_at("remeasured"));
    CHECK(results.at(4).bool_at("kit_fault"));
}

TEST_CASE("grader reports: JUnit XML is well formed and counts failures and errors", "[grader]") {
    test::TempDir dir;
    const GradeReport report = sample_report(dir.path());
    const std::string xml = junit_xml(report);
    CHECK(contains(xml, "<testsuites name=\"gsv-grade\" tests=\"5\" failures=\"3\" errors=\"1\""));
    CHECK(contains(xml, "<testsuite name=\"lab01\" tests=\"3\" failures=\"2\" errors=\"0\""));
    CHECK(contains(xml, "<testsuite name=\"lab02\" tests=\"2\" failures=\"1\" errors=\"1\""));
    CHECK(contains(xml, "<failure message=\"wrong image: max diff 200"));
    CHECK(contains(xml, "type=\"wrong image\""));
    CHECK(contains(xml, "<error message=\"reference failed: the reference solution failed: crash\" "
                        "type=\"reference failed\">"));
    CHECK(contains(xml, "&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;quotes&quot;"));
    CHECK(contains(xml, "name=\"phong [time] (L01-T3)\" classname=\"lab01\""));
    CHECK_FALSE(contains(xml, "<script>"));
    CHECK_FALSE(contains(xml, "\x01"));
    CHECK_FALSE(contains(xml, "\xff"));

    if (!have_python3()) {
        WARN("python3 is not on PATH: the JUnit XML was not parsed by a real XML parser");
        return;
    }
    const fs::path file = dir.write("junit.xml", xml);
    const auto [status, out] =
        run("python3 -c \"import xml.etree.ElementTree as E,sys; r=E.parse(sys.argv[1]).getroot(); "
            "print(len(r.findall('testsuite')), len(list(r.iter('testcase'))), len(list(r.iter('failure'))), "
            "len(list(r.iter('error'))), r.find('testsuite/testcase[2]/failure').text.count('<script>'))\" '" +
            file.string() + "' 2>&1");
    INFO(out);
    CHECK(status == 0);
    CHECK(out == "2 5 3 1 1\n");  // the student's text survives the round trip, unescaped
}

TEST_CASE("grader reports: HTML is self-contained and escapes student output", "[grader]") {
    test::TempDir dir;
    const GradeReport report = sample_report(dir.path());
    std::string page;
    REQUIRE_NOTHROW(page = html_report(report, dir.path()));
    CHECK_FALSE(contains(page, "<script"));
    CHECK(contains(page, "&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;quotes&quot;"));
    CHECK_FALSE(contains(page, "\x01"));
    // Four images were written (phong's two, shadow's two); each is embedded: the failing shadow's whole, starting with
    // the PNG signature in base64, the passed phong's as thumbnails (they matched; a class's reports stay small).
    CHECK(count(page, "src=\"data:image/png;base64,iVBORw0KGgo") == 2);
    CHECK(count(page, "src=\"data:image/jpeg;base64,/9j/") == 2);
    CHECK(count(page, "src=\"") == 4);  // and nothing else is loaded
    CHECK_FALSE(contains(page, "src=\"http"));
    CHECK_FALSE(contains(page, "href=\"http"));
    CHECK_FALSE(contains(page, "<link"));
    CHECK(contains(page, "lab01/shadow/diff.png is missing"));
    CHECK(contains(page, "<details><summary>images</summary>"));
    CHECK(contains(page, "12345678901234567890"));
    CHECK(contains(page, "5 / 19"));
    CHECK(contains(page, "user namespaces, no network"));
    CHECK(contains(page, "<th>SSIM</th><td>0.2500</td>"));
    CHECK(contains(page, "<th>PSNR</th><td>9.50 dB</td>"));
    CHECK(contains(page, "x 0&ndash;1, y 0&ndash;1"));
    CHECK(contains(page, "<td class=\"status\">too slow</td>"));

    // With no images at all (a folder that does not exist) every figure is a note.
    std::string bare;
    REQUIRE_NOTHROW(bare = html_report(report, dir.path("nowhere")));
    CHECK(count(bare, "data:image/png") == 0);
    CHECK(contains(bare, "lab01/phong/actual.png is missing"));

    // A file that is not a PNG is not embedded either.
    dir.write("lab01/phong/actual.png", "<svg onload=alert(1)>");
    const std::string fake = html_report(report, dir.path());
    CHECK(contains(fake, "lab01/phong/actual.png is not a PNG file"));
    CHECK(count(fake, "data:image/png;base64,") == 2);
    CHECK(count(fake, "data:image/jpeg;base64,") == 1);

    // A class's reports (--passed-pictures thumbnail): a failing case's pictures too as thumbnails, each a link to its
    // whole PNG beside the report; a picture that is not there is still a note, never a link.
    const std::string linked = html_report(report, dir.path(), ReportReader::Instructor, InstructorPictures::LinkedThumbnails);
    CHECK(count(linked, "data:image/png") == 0);
    CHECK(contains(linked, "<a href=\"lab01/shadow/actual.png\"><img alt=\"actual (yours)\" src=\"data:image/jpeg;base64,/9j/"));
    CHECK(contains(linked, "<a href=\"lab01/shadow/expected.png\"><img alt=\"expected\" src=\"data:image/jpeg;base64,/9j/"));
    CHECK_FALSE(contains(linked, "href=\"lab01/shadow/diff.png\""));
    CHECK(contains(linked, "lab01/shadow/diff.png is missing"));
}

TEST_CASE("grader reports: score table has rows, per-lab totals and the run's setup", "[grader]") {
    test::TempDir dir;
    const GradeReport report = sample_report(dir.path());
    const std::string table = score_table(report);
    INFO(table);
    std::istringstream lines(table);
    std::string header;
    std::getline(lines, header);
    CHECK(header.rfind("lab    check         todo    status            points  detail", 0) == 0);
    // A failing check's message goes whole below its row, folded.
    CHECK(contains(table, "lab01  phong [time]  L01-T3  too slow             0/2\n    1.80x the reference"));
    CHECK(contains(table, "lab02  fancy         L02-T2  reference failed     0/3"));
    // The long detail is whole, folded into lines of at most 110 characters.
    CHECK(contains(table, "\n    max diff 200, 3 of 4 px differ (75.00%)"));
    CHECK(count(table, "x") >= 200);
    std::istringstream folded(table);
    for (std::string line; std::getline(folded, line);)
        if (line.rfind("    ", 0) == 0) CHECK(line.size() <= 114);
    CHECK(contains(table, "  lab01       5 / 12      1 of 3 checks passed; built\n"));
    CHECK(contains(table, "  lab02       0 / 7       0 of 2 checks passed\n"));
    CHECK(contains(table, "builds that failed\n  lab02: lab02/main.cpp:12:5: error: expected ';'\n"));
    CHECK(contains(table, "total         5 / 19  (26%)\n"));
    CHECK(contains(table, "mode     instructor, hidden cases, timing\n"));
    CHECK(contains(table, "seed     12345678901234567890"));
    CHECK(contains(table, "sandbox  user namespaces, no network\n"));
    CHECK_FALSE(contains(table, "\x01"));

    GradeReport self_check = report;
    self_check.hidden_included = false;
    CHECK_FALSE(contains(score_table(self_check), "seed"));
}

TEST_CASE("grader reports: write_reports writes four files and names the one it cannot write", "[grader]") {
    test::TempDir dir;
    const GradeReport report = sample_report(dir.path());
    const fs::path out = dir.path("reports/nested");
    write_reports(report, out);
    for (const char* name : {"results.json", "report.json", "junit.xml", "report.html"}) {
        INFO(name);
        CHECK(fs::file_size(out / name) > 100);
    }
    CHECK(parse_json(test::read_text(out / "results.json"), "results.json").number_at("score") == 5);
    CHECK(test::read_text(out / "junit.xml") == junit_xml(report));

    // A folder where results.json should go: even root cannot open it as a file.
    const fs::path blocked = dir.path("blocked");
    fs::create_directories(blocked / "results.json");
    const std::string message = test::gsv_error_message([&] { write_reports(report, blocked); });
    CHECK(contains(message, "results.json"));
    CHECK(contains(message, "cannot write report"));

    // The output folder is a file.
    const fs::path file = dir.write("plain-file", "x");
    CHECK(contains(test::gsv_error_message([&] { write_reports(report, file); }), "plain-file"));
}

TEST_CASE("grader reports: wrong data shows in the table, report.json, JUnit and HTML", "[grader]") {
    test::TempDir dir;
    GradeReport report;
    report.mode = "instructor";
    report.sandbox = "off";
    CaseResult r = make_case("lab05", "ragged", "L05-T2", 0, 2, CaseStatus::WrongData);
    r.detail = "positions: 3 of 1,024 elements (0.29%) differ by more than 0.0001; first at element 1000: (NaN, 0, 0, 1) "
               "where the reference has (0.5, 0, 0, 1)";
    r.image.done = true;
    r.image.total_pixels = 4;
    r.image.psnr = std::numeric_limits<double>::infinity();
    r.image.ssim = 1;
    r.actual_png = "lab05/ragged/actual.png";
    r.expected_png = "lab05/ragged/expected.png";
    r.data.done = true;
    r.data.reference = "live";
    r.data.tolerance = {1e-4, 0.001};
    ArrayDiff positions;
    positions.name = "positions";
    positions.tolerance = r.data.tolerance;
    positions.count = positions.compared = 1024;
    positions.components = 4;
    positions.differing = 3;
    positions.non_finite = 1;
    positions.max_abs_diff = 0.25;
    positions.first = 1000;
    positions.first_actual = {std::numeric_limits<float>::quiet_NaN(), 0, 0, 1};
    positions.first_expected = {0.5f, 0, 0, 1};
    ArrayDiff velocities;
    velocities.name = "velocities";
    velocities.problem = "the lab handed in no 'velocities' array";
    r.data.arrays = {positions, velocities};
    report.results = {r};
    write_png(dir.path(r.actual_png), solid(2, 2, 1, 2, 3));
    write_png(dir.path(r.expected_png), solid(2, 2, 1, 2, 3));

    const std::string table = score_table(report);
    INFO(table);
    CHECK(contains(table, "lab05  ragged  L05-T2  wrong data     0/2\n    positions: 3 of 1,024 elements (0.29%)"));

    const Json json = parse_json(report_json(report), "report.json");
    const Json& result = json.array_at("results").at(0);
    CHECK(result.string_at("status") == "wrong data");
    CHECK_FALSE(result.bool_at("passed"));
    CHECK_FALSE(result.bool_at("kit_fault"));
    const Json& data = result.object_at("data");
    CHECK(data.bool_at("done"));
    CHECK_FALSE(data.contains("reference"));  // the result's own "reference" says against what
    CHECK(data.object_at("tolerance").number_at("max_abs") == 1e-4);
    REQUIRE(data.array_at("arrays").size() == 2);
    const Json& p = data.array_at("arrays").at(0);
    CHECK(p.string_at("name") == "positions");
    CHECK_FALSE(p.bool_at("passed"));
    CHECK(p.int_at("differing") == 3);
    CHECK(p.int_at("non_finite") == 1);
    CHECK(p.int_at("compared") == 1024);
    CHECK(p.object_at("first_difference").int_at("element") == 1000);
    CHECK(p.object_at("first_difference").array_at("actual").at(0).is_null());  // NaN: JSON has none
    CHECK(p.object_at("first_difference").array_at("expected").at(0).as_number() == 0.5);
    CHECK(contains(p.string_at("summary"), "1 of them NaN or Inf"));
    CHECK(data.array_at("arrays").at(1).string_at("problem") == "the lab handed in no 'velocities' array");
    CHECK(data.array_at("arrays").at(1).find("first_difference")->is_null());
    // A check without arrays says so.
    CHECK_FALSE(parse_json(report_json(sample_report(dir.path())), "r").array_at("results").at(0).object_at("data").bool_at("done"));

    const Json gradescope = parse_json(gradescope_json(report), "results.json");
    CHECK(gradescope.array_at("tests").at(0).string_at("status") == "failed");
    CHECK(gradescope.array_at("tests").at(0).string_at("output").rfind("wrong data: positions: 3 of 1,024", 0) == 0);

    const std::string xml = junit_xml(report);
    CHECK(contains(xml, "failures=\"1\" errors=\"0\""));
    CHECK(contains(xml, "<failure message=\"wrong data: positions: 3 of 1,024 elements"));
    CHECK(contains(xml, "type=\"wrong data\""));

    const std::string page = html_report(report, dir.path());
    CHECK(contains(page, "<td class=\"status\">wrong data</td>"));
    CHECK(contains(page, "<tr class=\"fail\">"));
    CHECK(contains(page, "<th>array</th>"));
    CHECK(contains(page, "<td>positions</td><td>1,024 &times; 4</td><td>1,024</td><td>3 (0.293%, allowed 0.100%)</td>"));
    CHECK(contains(page, "the lab handed in no &#39;velocities&#39; array"));
    CHECK(count(page, "data:image/png;base64,") == 2);  // actual and expected; the image passed, no difference
}

TEST_CASE("grader reports: the student's report.html has no seed and no hidden case's settings, the descriptions and the diagnosis, and thumbnails", "[grader]") {
    test::TempDir dir;
    GradeReport report = sample_report(dir.path());
    report.results[1].settings = {"light=secret-hidden-setting"};
    report.results[1].description = "a hidden description";
    report.results[1].reproduce = "build/bin/lab01 render --case shadow --set light=secret-hidden-setting";
    LabDiagnosis d;
    d.lab = "lab01";
    d.failing = {"phong-wrong", "shadow"};
    d.found.push_back({"L01-T1", "the normal stays in the model's space", "The hard cases", {"normals in model space"}, {"phong-wrong", "shadow"}});
    report.diagnoses.push_back(d);
    // A public failing case with full-size pictures: what the thumbnails replace.
    CaseResult wrong = make_case("lab01", "phong-wrong", "L01-T3", 0, 2, CaseStatus::WrongImage);
    wrong.visibility = "public";
    wrong.description = "Phong shading, the highlight where the light says";
    wrong.settings = {"shininess=64"};
    wrong.actual_png = "lab01/phong-wrong/actual.png";
    wrong.expected_png = "lab01/phong-wrong/expected.png";
    wrong.diff_png = "lab01/phong-wrong/diff.png";
    Image noise(256, 256);
    std::uint32_t state = 12345;
    for (auto& b : noise.rgba) b = static_cast<std::uint8_t>((state = state * 1664525u + 1013904223u) >> 24);
    for (const auto& png : {wrong.actual_png, wrong.expected_png, wrong.diff_png}) write_png(dir.path(png), noise);
    report.results.push_back(wrong);

    const std::string instructor = html_report(report, dir.path(), ReportReader::Instructor);
    const std::string student = html_report(report, dir.path(), ReportReader::Student);
    CHECK(contains(instructor, "12345678901234567890"));
    CHECK(contains(instructor, "secret-hidden-setting"));
    CHECK_FALSE(contains(student, "12345678901234567890"));
    CHECK_FALSE(contains(student, "secret-hidden-setting"));
    CHECK_FALSE(contains(student, "a hidden description"));
    CHECK_FALSE(contains(student, kHostileOutput.substr(0, 6) + "<"));  // a hidden case's output stays the instructor's
    CHECK(contains(student, "Phong shading, the highlight where the light says"));
    CHECK(contains(student, "shininess=64"));
    // The diagnosis, of the public case only: the hidden one is not counted to the student.
    CHECK((contains(student, "the normal stays in the model&#39;s space") || contains(student, "the normal stays in the model's space")));
    CHECK(contains(student, "data:image/jpeg;base64,"));
    CHECK_FALSE(contains(student, "data:image/png;base64,"));
    // Three full-size noise pictures are ~600 kB as PNG; as thumbnails a few tens of kB.
    CHECK(instructor.size() > 500000);
    CHECK(student.size() < 60000);
    // A hundred such failing cases (noise: no picture compresses worse) still make a report well under 2 MB: past its
    // budget a picture is a line saying where to see it.
    for (int i = 0; i < 99; ++i) report.results.push_back(wrong);
    const std::string hundred = html_report(report, dir.path(), ReportReader::Student);
    CHECK(hundred.size() < 1800000);
    CHECK(contains(hundred, "left out to keep this report small"));

    // write_reports: report.html is the instructor's in instructor grading, with the student's beside it; a
    // self-check's report.html is the student's, and none beside it.
    write_reports(report, dir.path("out"));
    CHECK(contains(test::read_text(dir.path("out/report.html")), "12345678901234567890"));
    CHECK_FALSE(contains(test::read_text(dir.path("out/student-report.html")), "12345678901234567890"));
    report.mode = "self-check";
    write_reports(report, dir.path("out"));
    CHECK_FALSE(contains(test::read_text(dir.path("out/report.html")), "data:image/png"));
    CHECK_FALSE(fs::exists(dir.path("out/student-report.html")));
}
