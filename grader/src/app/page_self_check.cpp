// The self-check in the browser page: every public case of the lab drawn in the page, as render mode draws it (the
// case's settings over the defaults, at the case file's size, into a float target where the browser has one), and
// compared with its golden image under the case's own tolerance by the grader's code (grader/src/judge/image_verdict.h),
// compiled to WebAssembly. The table is gsv-grade's (grader/src/report/report.h), so the page says what `gsv-grade --self-check`
// says. Its images (yours, golden, the difference, and compare's composite) go to /self-check/<case>/ in the page's
// memory file system, where the page shows them. Linked into the web pages only (cmake/web.cmake).
#include "common/app/app_session.h"
#include "common/app/app_web.h"
#include "common/core/error.h"
#include "common/image/comparison_image.h"
#include "common/image/image.h"
#include "common/io/json.h"
#include "common/app/known_mistake_pictures.h"
#include "grader/src/cases/cases.h"
#include "grader/src/diagnose/shipped_diagnosis.h"
#include "grader/src/judge/image_verdict.h"
#include "grader/src/judge/needs.h"
#include "grader/src/report/report.h"

#include <emscripten/bind.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

namespace gsv {
namespace {

namespace fs = std::filesystem;

const fs::path kOut = "/self-check";

// WebGL 2 is OpenGL ES 3.0: a case that needs more is the desktop's (or a newer ES's) to check.
bool fits_webgl2(const GradeCase& c) { return !c.es_version || !(GlVersion{3, 0} < *c.es_version); }

Image draw_case(Session& s, const LabCases& lab, const GradeCase& c) {
    s.params = s.defaults;
    for (const auto& setting : c.settings) s.params.set_assignment(setting);
    if (auto error = s.sync_params()) throw Error(*error);
    Framebuffer target = frame_target(s, lab.width, lab.height);
    target.bind();
    s.render_frame(Frame{lab.width, lab.height, 0.0});
    check_gl_error("drawing the case");
    return read_back(target).image;
}

// A failing case's pictures, kept for the diagnosis after the last case.
struct Drawn {
    Image actual, expected;
};

CaseResult check_case(Session& s, const LabCases& lab, const GradeCase& c, std::map<std::string, Drawn>& drawn) {
    CaseResult r = case_row(lab, c);
    r.reference = "golden";
    if (!fits_webgl2(c)) {
        r.status = CaseStatus::Unsupported;
        r.detail = "needs OpenGL ES " + c.es_version->str() + ", which WebGL 2 (ES 3.0) is not: checked on the desktop";
        return r;
    }
    const fs::path dir = kOut / c.name;
    fs::create_directories(dir);
    Image actual;
    try {
        actual = draw_case(s, lab, c);
    } catch (const std::exception& e) {
        r.status = CaseStatus::Error;
        r.detail = e.what();
        return r;
    }
    write_png(dir / "actual.png", actual);
    r.actual_png = (dir / "actual.png").string();
    const fs::path golden = KitLayout{s.assets->root()}.golden_image(lab.lab, c.name);
    const Image expected = read_png(golden);
    r.expected_png = golden.string();
    const ImageTolerance tolerance = lab.tolerance(c, false);
    const ImageDiff diff = judge_image(actual, expected, tolerance, c, r);
    if (!diff.size_mismatch) {
        write_png(dir / "diff.png", difference_heatmap(actual, expected, tolerance.max_channel_diff));
        r.diff_png = (dir / "diff.png").string();
        write_png(dir / "compare.png", compose_comparison(actual, expected, "yours: " + s.title() + " in the page",
                                                          "golden: " + c.name));
    }
    drawn[c.name] = {std::move(actual), expected};
    return r;
}

// What went wrong, as gsv-grade's self-check says it (grader/src/diagnose/shipped_diagnosis.h): the failing cases'
// pictures against the known mistakes' pictures the page has with the goldens; an explained case's compare.png gains
// the mistake's picture as a fourth view.
void diagnose(Session& s, const LabCases& lab, GradeReport& report, const std::map<std::string, Drawn>& drawn) {
    KnownMistakePictures shipped;
    try {
        shipped = read_known_mistake_pictures(s.assets->root(), lab.lab);
    } catch (const std::exception& e) {
        report.diagnosis_note = e.what();
        return;
    }
    LabDiagnosis none;
    none.lab = lab.lab;
    std::vector<ShippedFailure> failed;
    std::set<std::string> passed;
    for (const CaseResult& r : report.results) {
        if (r.status == CaseStatus::Passed) passed.insert(r.name);
        if (r.status == CaseStatus::NotDone && std::find(none.not_started.begin(), none.not_started.end(), r.todo) == none.not_started.end())
            none.not_started.push_back(r.todo);
        const auto it = drawn.find(r.name);
        if ((r.status == CaseStatus::WrongImage || r.status == CaseStatus::BlankImage) && it != drawn.end())
            failed.push_back({r.name, &it->second.actual, &it->second.expected});
    }
    if (!none.not_started.empty()) none.way_in = way_in(lab, report.results, 0);
    if (shipped.empty() || failed.empty()) {
        if (!none.not_started.empty()) report.diagnoses.push_back(none);
        return;
    }
    ShippedDiagnosis found = diagnose_shipped(shipped, failed, passed, s.assets->lab_dir());
    for (CaseResult& r : report.results) {
        if (const auto t = found.not_started_cases.find(r.name); t != found.not_started_cases.end()) r.mistake_todo = t->second;
        const auto m = found.mistake_of_case.find(r.name);
        if (m == found.mistake_of_case.end()) continue;
        const ShippedMistake& mistake = shipped.mistakes[m->second];
        r.mistake = mistake.says;
        r.mistake_todo = mistake.todo;
        r.mistake_sheet = mistake.sheet;
        if (found.drawn_together.count(r.name)) continue;  // two mistakes drew it together: no one picture of it
        const Drawn& d = drawn.at(r.name);
        MistakePanel panel{shipped_picture(shipped, m->second, r.name, d.actual.width, d.actual.height),
                           "looks like a known mistake in " + mistake.todo + ": " + mistake.says + " (its picture, reduced)"};
        const fs::path dir = kOut / r.name;
        write_png(dir / "mistake.png", panel.picture);
        r.mistake_png = (dir / "mistake.png").string();
        write_png(dir / "compare.png", compose_comparison(d.actual, d.expected, "yours: " + s.title() + " in the page",
                                                          "golden: " + r.name, nullptr, &panel));
    }
    for (const std::string& t : none.not_started)
        if (std::find(found.diagnosis.not_started.begin(), found.diagnosis.not_started.end(), t) == found.diagnosis.not_started.end())
            found.diagnosis.not_started.push_back(t);
    if (!found.diagnosis.not_started.empty()) found.diagnosis.way_in = way_in(lab, report.results, 0);
    report.diagnoses.push_back(std::move(found.diagnosis));
}

Json result_json(const CaseResult& r) {
    Json j = Json::object();
    j["name"] = r.name;
    j["todo"] = r.todo;
    j["points"] = r.points;
    j["max_points"] = r.max_points;
    j["status"] = status_name(r.status);
    j["passed"] = r.status == CaseStatus::Passed;
    j["detail"] = r.detail;
    j["max_channel_diff"] = r.image.max_channel_diff;
    j["differing_pixels"] = static_cast<double>(r.image.differing_pixels);
    j["total_pixels"] = static_cast<double>(r.image.total_pixels);
    j["tolerance_max_channel_diff"] = r.image.tolerance.max_channel_diff;
    j["tolerance_max_differing_fraction"] = r.image.tolerance.max_differing_fraction;
    j["actual"] = r.actual_png;
    j["diff"] = r.diff_png;
    j["mistake"] = r.mistake;
    j["mistake_todo"] = r.mistake_todo;
    j["mistake_sheet"] = r.mistake_sheet;
    j["mistake_picture"] = r.mistake_png;
    return j;
}

// Runs every public case (or the one named: compare's view of it); the page's own values are put back afterwards.
// Returns {"table": ..., "score": ..., "max_score": ..., "results": [...]}.
std::string self_check(const std::string& only) {
    Session* session = nullptr;
    try {
        session = &web_session();
    } catch (const std::exception& e) {
        Json out = Json::object();
        out["error"] = e.what();
        return out.dump(0);
    }
    Session& s = *session;
    const Params before = s.params;
    try {
        const LabCases lab = load_lab_cases(s.case_file());
        GradeReport report;
        report.submission = "this page";
        report.mode = "self-check";
        report.profile = "es";
        report.sandbox = "none needed: your own code, in your own browser";
        std::map<std::string, Drawn> drawn;
        for (const auto& c : lab.cases)
            if (c.visibility == "public" && (only.empty() || c.name == only)) report.results.push_back(check_case(s, lab, c, drawn));
        // Before the needs: a failure a known mistake explains is put on the mistake's TODO (grader/src/judge/needs.h).
        diagnose(s, lab, report, drawn);
        blame_needed_todos(lab, report.results, 0);
        s.params = before;
        if (auto error = s.sync_params()) throw Error(*error);
        Json out = Json::object();
        out["table"] = score_table(report);
        out["score"] = report.score();
        out["max_score"] = report.max_score();
        Json results = Json::array();
        for (const auto& r : report.results) results.push_back(result_json(r));
        out["results"] = results;
        return out.dump(0);
    } catch (const std::exception& e) {
        s.params = before;
        s.sync_params();
        Json out = Json::object();
        out["error"] = e.what();
        return out.dump(0);
    }
}

}  // namespace

EMSCRIPTEN_BINDINGS(gsv_page_self_check) { emscripten::function("selfCheck", &self_check); }

}  // namespace gsv
