#include "grader/src/diagnose/diagnosis.h"

#include "grader/src/judge/data_check.h"
#include "grader/src/judge/image_verdict.h"

#include <algorithm>

namespace gsv {

bool is_diagnosable(CaseStatus status) {
    return status == CaseStatus::WrongImage || status == CaseStatus::BlankImage || status == CaseStatus::WrongData;
}

bool mistake_fails(const LabCases& lab, const GradeCase& c, const LabRun& mistake, const ExpectedRender& expected,
                   const std::filesystem::path& kit) {
    if (mistake.status != CaseStatus::Passed || !mistake.image) return false;
    if (!image_passes(*mistake.image, expected.image, lab.tolerance(c, expected.live))) return true;
    if (!lab.checks_arrays()) return false;
    CaseResult row = case_row(lab, c);
    row.status = CaseStatus::Passed;
    if (expected.reference)
        check_case_data(lab, c, mistake, *expected.reference, row);
    else
        check_case_data(lab, c, mistake, kit, row);
    return row.status != CaseStatus::Passed;
}

bool student_matches(const LabCases& lab, const GradeCase& c, const LabRun& student, const LabRun& mistake) {
    if (student.status != CaseStatus::Passed || mistake.status != CaseStatus::Passed || !student.image || !mistake.image)
        return false;
    if (!image_passes(*student.image, *mistake.image, lab.tolerance(c, true))) return false;
    if (!lab.checks_arrays()) return true;
    CaseResult row = case_row(lab, c);
    row.status = CaseStatus::Passed;
    check_case_data(lab, c, student, mistake, row);
    return row.status == CaseStatus::Passed;
}

LabDiagnosis rank_mistakes(const std::string& lab, const std::vector<std::string>& failing,
                           const std::vector<KnownMistake>& mistakes, const std::vector<std::set<std::string>>& explains) {
    LabDiagnosis d;
    d.lab = lab;
    d.failing = failing;
    std::set<std::string> left(failing.begin(), failing.end());
    std::vector<bool> named(mistakes.size(), false);
    const auto still_explained = [&](std::size_t m) {
        std::vector<std::string> cases;
        for (const auto& f : failing)
            if (left.count(f) && explains[m].count(f)) cases.push_back(f);
        return cases;
    };
    while (!left.empty()) {
        std::size_t best = mistakes.size();
        std::size_t best_count = 0;
        for (std::size_t m = 0; m < mistakes.size(); ++m) {
            if (named[m]) continue;
            const std::size_t count = still_explained(m).size();
            if (count == 0) continue;
            if (best == mistakes.size() || count > best_count ||
                (count == best_count && explains[m].size() < explains[best].size())) {
                best = m;
                best_count = count;
            }
        }
        if (best == mistakes.size()) break;
        MistakeFound found{mistakes[best].todo, mistakes[best].says, mistakes[best].sheet, {}, still_explained(best)};
        for (std::size_t m = 0; m < mistakes.size(); ++m) {
            if (named[m] || explains[m] != explains[best]) continue;
            named[m] = true;
            found.names.push_back(mistakes[m].name);
        }
        for (const auto& c : found.cases) left.erase(c);
        d.found.push_back(std::move(found));
    }
    for (const auto& f : failing)
        if (left.count(f)) d.unexplained.push_back(f);
    return d;
}

}  // namespace gsv
