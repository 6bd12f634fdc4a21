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
#include "grader/src/cases/cases.h"
#include "grader/src/judge/image_verdict.h"
#include "grader/src/judge/needs.h"
#include "grader/src/report/report.h"

#include <emscripten/bind.h>

#include <filesystem>

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

CaseResult check_case(Session& s, const LabCases& lab, const GradeCase& c) {
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
    return r;
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
        for (const auto& c : lab.cases)
            if (c.visibility == "public" && (only.empty() || c.name == only)) report.results.push_back(check_case(s, lab, c));
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
