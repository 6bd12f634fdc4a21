#pragma once
// The data half of a case's check: the arrays the case checks (grader/src/cases/cases.h), compared with the reference's
// (grader/src/judge/array_compare.h), folded into the case's result beside its image check.
//
// Order: the image is checked first, then the numbers, whatever the image's outcome. A case passes only if both
// pass. When the image failed (wrong, blank or copied image) its status stands, since the picture is what a
// student sees and debugs first, and what is wrong with the numbers is appended to its detail; when only the
// numbers are wrong, the case is WrongData; when only the picture is wrong, its detail begins by saying the numbers
// match ("particles match the reference (positions, velocities); the picture differs: ..."). A picture within the
// margin renderers differ by (GpuMargin) with wrong numbers is WrongData. A reference without an array the case checks (a live reference that
// did not hand it in, a golden that is missing or unreadable) is the kit's fault: ReferenceFailed, as for images.
#include "grader/src/cases/cases.h"
#include "grader/src/core/grade_result.h"
#include "grader/src/run/lab_run.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

// Compares each expected array with the student's of the same name. `reference` is "live" or "golden".
DataCheck compare_data(const std::vector<DataArray>& student, const std::vector<ExpectedArray>& expected,
                       const ArrayTolerance& tolerance, const std::string& reference);

// Folds `data` into `r`, whose image check is done (Passed, WrongImage, BlankImage or CopiedImage), in the
// order above. `r` keeps its points only if both passed.
void apply_data_check(CaseResult& r, const DataCheck& data);

// Against the live reference, end to end: for a lab that checks arrays, the case's arrays of `reference` (its
// list, else every array the reference hands in) compared with `student`'s and folded into `r`. `r` holds the
// student's run and, where it ran, the image check; `reference` passed. Nothing to do for other labs.
void check_case_data(const LabCases& lab, const GradeCase& c, const LabRun& student, const LabRun& reference,
                     CaseResult& r);
// The same against the goldens in `kit` (self-check): the case's list, else every golden the case has. A case
// with no goldens whose lab hands in arrays anyway has lost its goldens.
void check_case_data(const LabCases& lab, const GradeCase& c, const LabRun& student, const std::filesystem::path& kit,
                     CaseResult& r);

}  // namespace gsv
