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
#include "grader/src/cases/case_row.h"
#include "grader/src/cases/cases.h"
#include "grader/src/diagnose/shipped_diagnosis.h"
#include "grader/src/judge/image_verdict.h"
#include "grader/src/judge/needs.h"
#include "grader/src/report/report.h"

#include <emscripten/bind.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

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

// A self-check under way: the page checks one case a call (selfCheckStep), drawing between them, so a long check shows
// its progress and never holds the page for more than a case.
struct PendingCheck {
    LabCases lab;
    std::vector<const GradeCase*> todo;  // the cases to check, in the case file's order
    std::size_t next = 0;
    GradeReport report;
    std::map<std::string, Drawn> drawn;
    Params before;
    bool active = false;
};

PendingCheck& pending() {
    static PendingCheck check;  // the page's one self-check, beside its one session
    return check;
}

std::string error_json(const std::string& what) {
    Json out = Json::object();
    out["error"] = what;
    return out.dump(0);
}

// Starts a self-check of the public cases `only` selects: all (""), one case by name (compare's view of it) or a TODO's
// cases by its id ("L01-T2"). Returns what is wrong where it cannot start (an id or name the case file does not have).
std::optional<std::string> start_check(const std::string& only) {
    PendingCheck& p = pending();
    try {
        Session& s = web_session();
        if (p.active) {  // a check the page left unfinished: the page's own values back first
            s.params = p.before;
            s.sync_params();
        }
        p = PendingCheck{};
        p.lab = load_lab_cases(s.case_file());
        for (const auto& c : p.lab.cases)
            if (c.visibility == "public" && (only.empty() || c.name == only || c.todo == only)) p.todo.push_back(&c);
        if (p.todo.empty()) return "no public case is named or checks '" + only + "' in " + s.case_file().string();
        p.report.submission = "this page";
        p.report.mode = "self-check";
        p.report.profile = "es";
        p.report.sandbox = "none needed: your own code, in your own browser";
        p.before = s.params;
        p.active = true;
        return std::nullopt;
    } catch (const std::exception& e) {
        p.active = false;
        return std::string(e.what());
    }
}

// The page's start: {"cases": [names]} or {"error": ...}.
std::string self_check_start(const std::string& only) {
    if (const auto error = start_check(only)) return error_json(*error);
    Json names = Json::array();
    for (const GradeCase* c : pending().todo) names.push_back(c->name);
    Json out = Json::object();
    out["cases"] = names;
    return out.dump(0);
}

// Checks the next case. Returns {"done": n, "total": m, "name": the case just checked, "passed": bool}.
std::string self_check_step() {
    PendingCheck& p = pending();
    if (!p.active) return error_json("no self-check is under way");
    Json out = Json::object();
    if (p.next < p.todo.size()) {
        const GradeCase& c = *p.todo[p.next++];
        p.report.results.push_back(check_case(web_session(), p.lab, c, p.drawn));
        out["name"] = c.name;
        out["passed"] = p.report.results.back().status == CaseStatus::Passed;
    }
    out["done"] = static_cast<int>(p.next);
    out["total"] = static_cast<int>(p.todo.size());
    return out.dump(0);
}

// Ends the check: the known mistakes and the needed TODOs worked out over the cases checked, the page's own values put
// back. Returns {"table": ..., "score": ..., "max_score": ..., "results": [...]}.
std::string self_check_finish() {
    PendingCheck& p = pending();
    if (!p.active) return error_json("no self-check is under way");
    p.active = false;
    Session& s = web_session();
    try {
        // Before the needs: a failure a known mistake explains is put on the mistake's TODO (grader/src/judge/needs.h).
        diagnose(s, p.lab, p.report, p.drawn);
        blame_needed_todos(p.lab, p.report.results, 0);
        s.params = p.before;
        if (auto error = s.sync_params()) throw Error(*error);
        Json out = Json::object();
        out["table"] = score_table(p.report);
        out["score"] = p.report.score();
        out["max_score"] = p.report.max_score();
        Json results = Json::array();
        for (const auto& r : p.report.results) results.push_back(result_json(r));
        out["results"] = results;
        return out.dump(0);
    } catch (const std::exception& e) {
        s.params = p.before;
        s.sync_params();
        return error_json(e.what());
    }
}

// The public cases as the page's self-check takes them: {"cases": [{"name", "todo", "points", "desktop_only", "es"}]}
// (desktop_only: the case needs more than WebGL 2's ES 3.0, so the page cannot earn its points).
std::string self_check_cases() {
    try {
        Session& s = web_session();
        const LabCases lab = load_lab_cases(s.case_file());
        Json cases = Json::array();
        for (const auto& c : lab.cases) {
            if (c.visibility != "public") continue;
            Json j = Json::object();
            j["name"] = c.name;
            j["todo"] = c.todo;
            j["points"] = c.points;
            j["desktop_only"] = !fits_webgl2(c);
            j["es"] = c.es_version ? c.es_version->str() : std::string("3.0");
            cases.push_back(j);
        }
        Json out = Json::object();
        out["cases"] = cases;
        return out.dump(0);
    } catch (const std::exception& e) {
        return error_json(e.what());
    }
}

// The whole check in one call: every public case, one by name, or a TODO's.
std::string self_check(const std::string& only) {
    if (const auto error = start_check(only)) return error_json(*error);
    while (pending().next < pending().todo.size()) self_check_step();
    return self_check_finish();
}

}  // namespace

EMSCRIPTEN_BINDINGS(gsv_page_self_check) {
    emscripten::function("selfCheck", &self_check);
    emscripten::function("selfCheckStart", &self_check_start);
    emscripten::function("selfCheckStep", &self_check_step);
    emscripten::function("selfCheckFinish", &self_check_finish);
    emscripten::function("selfCheckCases", &self_check_cases);
}

}  // namespace gsv
