#include "grader/src/report/report.h"
#include "grader/src/report/report_format.h"

#include "common/io/json.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>

namespace gsv {
namespace {

// JSON has no infinity or NaN. PSNR is +inf for identical images (and a ratio can be inf when the
// reference measured 0 ms), so a non-finite value is written as null: "no finite value". Json::dump
// would print null as well; doing it here keeps that a decision of the report, not of the printer.
Json number_or_null(double value) {
    return std::isfinite(value) ? Json(value) : Json(nullptr);
}

// The seed is 64-bit and Json numbers are doubles, exact only to 2^53: as a decimal string it
// survives, so a tool can hand it back to the grader to draw the same hidden cases.
std::string seed_text(std::uint64_t seed) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%" PRIu64, seed);
    return buffer;
}

// Student output is arbitrary bytes; JSON must be valid UTF-8 or Gradescope rejects the whole file.
Json text(const std::string& value) { return Json(valid_utf8(value)); }

Json image_json(const ImageCheck& image) {
    Json j = Json::object();
    j["done"] = image.done;
    Json tolerance = Json::object();
    tolerance["max_channel_diff"] = image.tolerance.max_channel_diff;
    tolerance["max_differing_fraction"] = number_or_null(image.tolerance.max_differing_fraction);
    // 0: each pixel against the one at its own place; r: matched within r pixels, both ways (image_compare.h).
    tolerance["neighbourhood"] = image.tolerance.neighbourhood;
    j["tolerance"] = tolerance;
    j["max_channel_diff"] = image.max_channel_diff;
    j["differing_pixels"] = image.differing_pixels;
    j["total_pixels"] = image.total_pixels;
    j["psnr"] = number_or_null(image.psnr);  // null: identical RGB
    j["ssim"] = number_or_null(image.ssim);
    Json box = Json::object();
    box["x0"] = image.diff_x0;
    box["y0"] = image.diff_y0;
    box["x1"] = image.diff_x1;
    box["y1"] = image.diff_y1;
    // x1 < x0 means no pixel differs; null says so without a tool having to know the convention.
    j["diff_box"] = image.diff_x1 < image.diff_x0 ? Json(nullptr) : box;
    // How far the whole picture is moved against the reference (pixels; x right, y down).
    Json offset = Json::array();
    offset.push_back(number_or_null(image.offset_x));
    offset.push_back(number_or_null(image.offset_y));
    j["offset"] = offset;
    return j;
}

Json floats_json(const std::vector<float>& values) {
    Json j = Json::array();
    for (const float v : values) j.push_back(number_or_null(v));  // null: NaN or Inf
    return j;
}

Json data_json(const DataCheck& data) {
    Json j = Json::object();
    j["done"] = data.done;  // against what: the result's "reference"
    Json tolerance = Json::object();
    tolerance["max_abs"] = number_or_null(data.tolerance.max_abs);
    tolerance["max_differing_fraction"] = number_or_null(data.tolerance.max_differing_fraction);
    j["tolerance"] = tolerance;
    Json arrays = Json::array();
    for (const auto& a : data.arrays) {
        Json e = Json::object();
        e["name"] = text(a.name);
        e["passed"] = a.within();
        e["problem"] = text(a.problem);  // "": the arrays were compared
        e["count"] = static_cast<double>(a.count);
        e["components"] = a.components;
        e["compared"] = static_cast<double>(a.compared);  // fewer than count: a golden's sample
        e["differing"] = static_cast<double>(a.differing);
        e["non_finite"] = static_cast<double>(a.non_finite);
        e["max_abs_diff"] = number_or_null(a.max_abs_diff);
        if (a.differing > 0) {
            Json first = Json::object();
            first["element"] = static_cast<double>(a.first);
            first["actual"] = floats_json(a.first_actual);
            first["expected"] = floats_json(a.first_expected);
            e["first_difference"] = first;
        } else {
            e["first_difference"] = nullptr;
        }
        e["summary"] = text(a.summary());
        arrays.push_back(e);
    }
    j["arrays"] = arrays;
    return j;
}

Json timing_json(const TimingCheck& timing) {
    Json j = Json::object();
    j["done"] = timing.done;
    j["student_ms"] = number_or_null(timing.student_ms);
    j["reference_ms"] = number_or_null(timing.reference_ms);
    j["ratio"] = number_or_null(timing.ratio);
    j["max_ratio"] = number_or_null(timing.max_ratio);
    j["rounds"] = timing.rounds;
    j["remeasured"] = timing.remeasured;
    return j;
}

Json result_json(const CaseResult& r) {
    Json j = Json::object();
    j["lab"] = text(r.lab);
    j["name"] = text(r.name);
    j["title"] = text(check_title(r));
    j["todo"] = text(r.todo);
    j["description"] = text(r.description);
    j["visibility"] = text(r.visibility);
    j["kind"] = text(r.kind);
    Json settings = Json::array();
    for (const auto& s : r.settings) settings.push_back(text(s));
    j["settings"] = settings;
    j["points"] = number_or_null(r.points);
    j["max_points"] = number_or_null(r.max_points);
    j["status"] = status_name(r.status);
    j["passed"] = r.status == CaseStatus::Passed;
    j["kit_fault"] = is_kit_fault(r.status);
    j["detail"] = text(r.detail);
    j["reproduce"] = text(r.reproduce);
    j["output"] = text(r.output);
    j["reference"] = text(r.reference);
    j["seconds"] = number_or_null(r.seconds);
    j["reference_seconds"] = number_or_null(r.reference_seconds);
    j["frame_ms"] = number_or_null(r.frame_ms);
    j["image"] = image_json(r.image);
    j["data"] = data_json(r.data);
    j["timing"] = timing_json(r.timing);
    j["actual_png"] = text(r.actual_png);
    j["expected_png"] = text(r.expected_png);
    j["diff_png"] = text(r.diff_png);
    // A known mistake that explains this failure (grader/src/diagnose/): what it says, its TODO, the sheet's section,
    // its picture of this case. All "" where none does.
    j["mistake"] = text(r.mistake);
    j["mistake_todo"] = text(r.mistake_todo);
    j["mistake_sheet"] = text(r.mistake_sheet);
    j["mistake_png"] = text(r.mistake_png);
    return j;
}

Json strings_json(const std::vector<std::string>& items) {
    Json j = Json::array();
    for (const auto& item : items) j.push_back(text(item));
    return j;
}

Json diagnosis_json(const LabDiagnosis& d) {
    Json j = Json::object();
    j["lab"] = text(d.lab);
    j["failing"] = strings_json(d.failing);
    Json found = Json::array();
    for (const auto& f : d.found) {
        Json m = Json::object();
        m["todo"] = text(f.todo);
        m["says"] = text(f.says);
        m["sheet"] = text(f.sheet);
        m["names"] = strings_json(f.names);
        m["cases"] = strings_json(f.cases);
        m["with_earlier"] = f.with_earlier;
        found.push_back(m);
    }
    j["found"] = found;
    j["unexplained"] = strings_json(d.unexplained);
    j["not_started"] = strings_json(d.not_started);
    j["compare"] = text(d.compare);
    j["way_in"] = text(d.way_in);
    return j;
}

// One line for the whole submission. Only public checks are counted: Gradescope shows this line at
// once, and counting hidden checks would tell the student how they fared before the due date.
std::string summary_line(const GradeReport& report) {
    int public_checks = 0, public_passed = 0;
    for (const auto& r : report.results) {
        if (r.visibility != "public") continue;
        ++public_checks;
        if (r.status == CaseStatus::Passed) ++public_passed;
    }
    std::string line = std::to_string(public_passed) + " of " + std::to_string(public_checks) + " public checks passed";
    std::string failed_builds;
    for (const auto& b : report.builds)
        if (!b.ok) failed_builds += (failed_builds.empty() ? "" : ", ") + b.lab;
    if (!failed_builds.empty()) line += "; did not build: " + failed_builds;
    for (const auto& r : report.results)
        if (is_kit_fault(r.status)) {
            line += "; some checks could not be graded (the reference failed), tell the course staff";
            break;
        }
    return line + ".";
}

}  // namespace

std::string gradescope_json(const GradeReport& report) {
    Json root = Json::object();
    root["score"] = number_or_null(report.score());
    root["execution_time"] = static_cast<long>(std::lround(std::isfinite(report.seconds) ? report.seconds : 0.0));
    // What the failures come down to, as the student may be told: public cases only, never a hidden one's name.
    std::string output = summary_line(report);
    for (const auto& d : report.diagnoses) {
        const std::vector<std::string> lines = diagnosis_lines(student_diagnosis(d, report));
        if (lines.empty()) continue;
        output += "\n\n" + d.lab + ":";
        for (const auto& line : lines) output += "\n" + line;
    }
    root["output"] = text(output);
    // Plain text: student output can contain anything, and must not be read as HTML or Markdown.
    root["output_format"] = "text";
    root["test_output_format"] = "text";
    Json tests = Json::array();
    for (const auto& r : report.results) {
        Json t = Json::object();
        t["name"] = text(check_title(r));
        t["score"] = number_or_null(r.points);
        t["max_score"] = number_or_null(r.max_points);
        t["status"] = r.status == CaseStatus::Passed ? "passed" : "failed";
        std::string output = check_output(r);
        if (output.back() != '\n') output += '\n';
        t["output"] = text(output);
        // Fail closed: a visibility other than "public" (a typo in a case file) is treated as hidden.
        t["visibility"] = r.visibility == "public" ? "visible" : "after_due_date";
        Json tags = Json::array();
        if (!r.todo.empty()) tags.push_back(text(r.todo));
        t["tags"] = tags;
        tests.push_back(t);
    }
    root["tests"] = tests;
    return root.dump(2) + "\n";
}

std::string report_json(const GradeReport& report) {
    Json root = Json::object();
    root["submission"] = text(report.submission);
    root["mode"] = text(report.mode);
    root["profile"] = text(report.profile);
    root["renderer"] = text(report.renderer);  // "": no lab reported one
    Json goldens = Json::object();
    for (const auto& [lab, renderer] : report.golden_renderers) goldens[lab] = text(renderer);
    root["golden_renderers"] = goldens;  // by lab: what the goldens were rendered on (self-check)
    root["seed"] = seed_text(report.seed);
    root["hidden_included"] = report.hidden_included;
    root["timing_included"] = report.timing_included;
    root["sandbox"] = text(report.sandbox);
    root["references"] = text(report.references);
    root["seconds"] = number_or_null(report.seconds);
    root["score"] = number_or_null(report.score());
    root["max_score"] = number_or_null(report.max_score());
    Json builds = Json::array();
    for (const auto& b : report.builds) {
        Json j = Json::object();
        j["lab"] = text(b.lab);
        j["ok"] = b.ok;
        j["seconds"] = number_or_null(b.seconds);
        j["origin"] = text(b.origin);
        j["log"] = text(b.log);
        builds.push_back(j);
    }
    root["builds"] = builds;
    Json results = Json::array();
    for (const auto& r : report.results) results.push_back(result_json(r));
    root["results"] = results;
    root["diagnose"] = text(report.diagnose);
    Json diagnoses = Json::array();
    for (const auto& d : report.diagnoses) diagnoses.push_back(diagnosis_json(d));
    root["diagnoses"] = diagnoses;
    root["diagnosis_note"] = text(report.diagnosis_note);
    // --regrade-only changed: which labs this run graded, and which kept the last run's rows.
    if (!report.regraded.empty() || !report.kept.empty()) {
        Json regraded = Json::array(), kept = Json::array();
        for (const auto& lab : report.regraded) regraded.push_back(text(lab));
        for (const auto& lab : report.kept) kept.push_back(text(lab));
        root["regraded"] = regraded;
        root["kept"] = kept;
    }
    return root.dump(2) + "\n";
}

}  // namespace gsv
