#include "grader/src/diagnose/diagnosis.h"

#include "grader/src/cases/case_row.h"
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

}  // namespace gsv
