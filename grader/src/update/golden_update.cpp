#include "grader/src/update/golden_update.h"

#include "common/app/kit_layout.h"
#include "common/image/image.h"
#include "grader/src/golden/array_golden.h"
#include "grader/src/golden/golden_renderers.h"
#include "grader/src/grade/session.h"
#include "grader/src/judge/needs.h"

#include <algorithm>
#include <map>
#include <string>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// A sampled golden of each array the case checks; goldens of arrays it no longer checks go, so that the
// self-check (which checks every golden a case has) does not look for them.
void update_golden_arrays(const fs::path& kit, const LabCases& lab, const GradeCase& c, const LabRun& ref, CaseResult& r) {
    std::vector<std::string> names;
    if (c.arrays) {
        names = *c.arrays;
    } else {
        for (const auto& a : ref.arrays) names.push_back(a.name);
    }
    for (const auto& name : golden_array_names(kit, lab.lab, c.name))
        if (std::find(names.begin(), names.end(), name) == names.end()) fs::remove(array_golden_path(kit, lab.lab, c.name, name));
    for (const auto& name : names) {
        const auto a = std::find_if(ref.arrays.begin(), ref.arrays.end(), [&](const DataArray& x) { return x.name == name; });
        if (a == ref.arrays.end()) {
            r.status = CaseStatus::ReferenceFailed;
            r.detail = "the reference solution handed in no '" + name + "' array, which the case checks";
            return;
        }
        write_array_golden(array_golden_path(kit, lab.lab, c.name, name), sample_array(*a));
    }
    if (!names.empty()) r.detail += " and " + std::to_string(names.size()) + (names.size() == 1 ? " array" : " arrays");
}

// `renderer`: the GL renderer the reference ran on, where it said.
CaseResult update_golden(GradingSession& s, const LabCases& lab, const GradeCase& c, std::string& renderer) {
    CaseResult r = s.result_for(lab, c);
    const LabRun ref = s.reference.render(lab.lab + "_solution", lab, c, s.limits(lab, false));
    r.status = ref.status;
    r.output = ref.process.output;
    r.detail = ref.detail;
    if (ref.status == CaseStatus::Passed) {
        const fs::path golden = KitLayout{s.kit}.golden_image(lab.lab, c.name);
        fs::create_directories(golden.parent_path());
        write_png(golden, *ref.image);
        r.detail = "wrote " + golden.string();
        if (!ref.renderer.empty()) renderer = ref.renderer;
        if (lab.checks_arrays()) update_golden_arrays(s.kit, lab, c, ref, r);
    }
    return r;
}

}  // namespace

GradeReport update_goldens(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress) {
    GradingSession s(options, progress, RunPurpose::UpdateGoldens);
    s.set_up();
    std::map<std::string, std::string> rendered;  // lab -> the renderer its goldens just came from
    for (const LabCases& lab : s.labs) {
        const std::size_t first = s.report.results.size();
        for (const auto& c : lab.cases)
            if (c.visibility == "public") s.record(update_golden(s, lab, c, rendered[lab.lab]));
        // As grading does: a reference that failed where a TODO it needs failed too says so.
        blame_needed_todos(lab, s.report.results, first);
    }
    // The goldens just written, and the renderer they came from, beside the record of the other labs'.
    const fs::path record = KitLayout{s.kit}.golden_renderers();
    auto renderers = read_golden_renderers(record);
    bool changed = false;
    for (const auto& [lab, renderer] : rendered)
        if (!renderer.empty()) renderers[lab] = renderer, changed = true;
    if (changed) write_golden_renderers(record, renderers);
    return s.finish();
}

}  // namespace gsv
