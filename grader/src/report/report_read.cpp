// report.json read back (report.h's read_report_json): what an earlier run found, so that a regrade of some labs
// (--regrade-only changed) keeps the others' rows as they were and writes every report again from one GradeReport.
#include "grader/src/report/report.h"

#include "common/core/error.h"
#include "common/io/json.h"

#include <cmath>
#include <limits>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// report_json writes a non-finite number as null; reading one back gives what it stood for.
double number_or(const Json& object, const std::string& key, double when_null) {
    const Json& value = object.member_at(key);
    return value.is_null() ? when_null : value.as_number();
}

std::vector<float> floats(const Json& values) {
    std::vector<float> out;
    for (const Json& v : values.as_array())
        out.push_back(v.is_null() ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(v.as_number()));
    return out;
}

CaseStatus status_named(const std::string& name, const std::string& where) {
    for (int s = 0; s <= static_cast<int>(kLastCaseStatus); ++s)
        if (name == status_name(static_cast<CaseStatus>(s))) return static_cast<CaseStatus>(s);
    throw Error(where + ": unknown status '" + name + "'");
}

ImageCheck image_check(const Json& j) {
    ImageCheck image;
    image.done = j.bool_at("done");
    const Json& tolerance = j.member_at("tolerance");
    image.tolerance.max_channel_diff = tolerance.int_at("max_channel_diff");
    image.tolerance.max_differing_fraction = number_or(tolerance, "max_differing_fraction", 0);
    image.tolerance.neighbourhood = tolerance.int_at("neighbourhood");
    image.max_channel_diff = j.int_at("max_channel_diff");
    image.differing_pixels = static_cast<long>(j.number_at("differing_pixels"));
    image.total_pixels = static_cast<long>(j.number_at("total_pixels"));
    image.psnr = number_or(j, "psnr", std::numeric_limits<double>::infinity());
    image.ssim = number_or(j, "ssim", 0);
    if (const Json& box = j.member_at("diff_box"); !box.is_null()) {
        image.diff_x0 = box.int_at("x0");
        image.diff_y0 = box.int_at("y0");
        image.diff_x1 = box.int_at("x1");
        image.diff_y1 = box.int_at("y1");
    }
    if (const Json* offset = j.find("offset"); offset && offset->is_array() && offset->size() == 2) {
        image.offset_x = offset->at(0).is_number() ? offset->at(0).as_number() : 0;
        image.offset_y = offset->at(1).is_number() ? offset->at(1).as_number() : 0;
    }
    return image;
}

DataCheck data_check(const Json& j, const std::string& reference) {
    DataCheck data;
    data.done = j.bool_at("done");
    data.reference = reference;
    const Json& tolerance = j.member_at("tolerance");
    data.tolerance.max_abs = number_or(tolerance, "max_abs", 0);
    data.tolerance.max_differing_fraction = number_or(tolerance, "max_differing_fraction", 0);
    for (const Json& e : j.array_at("arrays").as_array()) {
        ArrayDiff a;
        a.name = e.string_at("name");
        a.tolerance = data.tolerance;
        a.problem = e.string_at("problem");
        a.count = static_cast<std::size_t>(e.number_at("count"));
        a.components = e.int_at("components");
        a.compared = static_cast<std::size_t>(e.number_at("compared"));
        a.differing = static_cast<std::size_t>(e.number_at("differing"));
        a.non_finite = static_cast<std::size_t>(e.number_at("non_finite"));
        a.max_abs_diff = number_or(e, "max_abs_diff", std::numeric_limits<double>::infinity());
        if (const Json& first = e.member_at("first_difference"); !first.is_null()) {
            a.first = static_cast<std::size_t>(first.number_at("element"));
            a.first_actual = floats(first.member_at("actual"));
            a.first_expected = floats(first.member_at("expected"));
        }
        data.arrays.push_back(std::move(a));
    }
    return data;
}

TimingCheck timing_check(const Json& j) {
    TimingCheck timing;
    timing.done = j.bool_at("done");
    timing.student_ms = number_or(j, "student_ms", 0);
    timing.reference_ms = number_or(j, "reference_ms", 0);
    timing.ratio = number_or(j, "ratio", std::numeric_limits<double>::infinity());
    timing.max_ratio = number_or(j, "max_ratio", 0);
    timing.rounds = j.int_at("rounds");
    timing.remeasured = j.bool_at("remeasured");
    return timing;
}

CaseResult case_result(const Json& j, const std::string& where) {
    CaseResult r;
    r.lab = j.string_at("lab");
    r.name = j.string_at("name");
    r.todo = j.string_at("todo");
    r.description = j.string_at("description");
    r.visibility = j.string_at("visibility");
    r.kind = j.string_at("kind");
    for (const Json& s : j.array_at("settings").as_array()) r.settings.push_back(s.as_string());
    r.points = number_or(j, "points", 0);
    r.max_points = number_or(j, "max_points", 0);
    r.status = status_named(j.string_at("status"), where);
    r.detail = j.string_at("detail");
    r.reproduce = j.string_at("reproduce");
    r.output = j.string_at("output");
    r.reference = j.string_at("reference");
    r.seconds = number_or(j, "seconds", 0);
    r.reference_seconds = number_or(j, "reference_seconds", 0);
    r.frame_ms = number_or(j, "frame_ms", 0);
    r.image = image_check(j.member_at("image"));
    r.data = data_check(j.member_at("data"), r.reference);
    r.timing = timing_check(j.member_at("timing"));
    r.actual_png = j.string_at("actual_png");
    r.expected_png = j.string_at("expected_png");
    r.diff_png = j.string_at("diff_png");
    r.mistake = j.string_or("mistake", "");
    r.mistake_todo = j.string_or("mistake_todo", "");
    r.mistake_sheet = j.string_or("mistake_sheet", "");
    r.mistake_png = j.string_or("mistake_png", "");
    return r;
}

}  // namespace

GradeReport read_report_json(const fs::path& file) {
    const Json root = read_json_file(file);
    const std::string where = file.string();
    try {
        GradeReport report;
        report.submission = root.string_at("submission");
        report.mode = root.string_at("mode");
        report.profile = root.string_at("profile");
        report.renderer = root.string_at("renderer");
        for (const auto& [lab, renderer] : root.member_at("golden_renderers").as_object()) report.golden_renderers[lab] = renderer.as_string();
        const std::string seed = root.string_at("seed");
        if (seed.empty() || seed.find_first_not_of("0123456789") != std::string::npos) throw Error("seed '" + seed + "' is not a whole number");
        report.seed = std::stoull(seed);
        report.hidden_included = root.bool_at("hidden_included");
        report.timing_included = root.bool_at("timing_included");
        report.sandbox = root.string_at("sandbox");
        if (const Json* references = root.find("references")) report.references = references->as_string();
        report.seconds = number_or(root, "seconds", 0);
        for (const Json& b : root.array_at("builds").as_array()) {
            LabBuild build;
            build.lab = b.string_at("lab");
            build.ok = b.bool_at("ok");
            build.seconds = number_or(b, "seconds", 0);
            build.origin = b.string_at("origin");
            build.log = b.string_at("log");
            report.builds.push_back(std::move(build));
        }
        for (const Json& r : root.array_at("results").as_array()) report.results.push_back(case_result(r, where));
        report.diagnose = root.string_or("diagnose", "off");
        report.diagnosis_note = root.string_or("diagnosis_note", "");
        if (const Json* diagnoses = root.find("diagnoses"))
            for (const Json& j : diagnoses->as_array()) {
                const auto strings = [&](const Json& from, const char* key) {
                    std::vector<std::string> items;
                    for (const Json& item : from.array_at(key).as_array()) items.push_back(item.as_string());
                    return items;
                };
                LabDiagnosis d;
                d.lab = j.string_at("lab");
                d.failing = strings(j, "failing");
                for (const Json& f : j.array_at("found").as_array())
                    d.found.push_back({f.string_at("todo"), f.string_at("says"), f.string_at("sheet"), strings(f, "names"), strings(f, "cases"),
                                       f.find("with_earlier") && f.bool_at("with_earlier")});
                d.unexplained = strings(j, "unexplained");
                d.not_started = strings(j, "not_started");
                d.compare = j.string_or("compare", "");
                d.way_in = j.string_or("way_in", "");
                report.diagnoses.push_back(std::move(d));
            }
        for (const char* list : {"regraded", "kept"})
            if (const Json* labs = root.find(list))
                for (const Json& lab : labs->as_array()) (std::string(list) == "regraded" ? report.regraded : report.kept).push_back(lab.as_string());
        return report;
    } catch (const Error& e) {
        const std::string what = e.what();
        throw Error(what.rfind(where, 0) == 0 ? what : where + ": " + what);
    }
}

}  // namespace gsv
