#pragma once
// From pictures to the mistake (issue 40): each failing case's picture (and numbers, where the lab hands them in) is
// compared with each known mistake's picture of the same case (grader/src/diagnose/known_mistakes.h), by the case's
// own comparator and live tolerance: both were rendered on this machine. Across the lab's failing cases, the fewest
// mistakes that explain the most of them are named, in order; a failure none explains is said to be unexplained, never
// given the nearest name. A mistake explains a case only where its own picture fails that case: one that changes
// nothing there explains nothing there.
#include "grader/src/cases/cases.h"
#include "grader/src/diagnose/known_mistakes.h"
#include "grader/src/diagnose/ranking.h"
#include "grader/src/core/grade_result.h"
#include "grader/src/run/lab_run.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gsv {

// Whether a row's failure is one a known mistake can explain: a wrong picture, a blank one or wrong numbers (a mistake
// is an edit that renders). Not done is "not started"; a crash, a timeout, a copied image and the like say what the lab
// did, and a GPU margin is a difference between renderers.
bool is_diagnosable(CaseStatus status);

// The expected render of a case: the picture the student's failed against (a live reference's or the golden), and the
// live reference run where there is one (its arrays), else the kit whose goldens hold the arrays.
struct ExpectedRender {
    Image image;
    std::optional<LabRun> reference;
    bool live = false;
};

// Whether `mistake`'s render of case `c` fails against `expected` (picture or numbers) as a student's would: a mistake
// that changes nothing there explains nothing there.
bool mistake_fails(const LabCases& lab, const GradeCase& c, const LabRun& mistake, const ExpectedRender& expected,
                   const std::filesystem::path& kit);
// Whether the student's render of case `c` is the mistake's, as the case would judge it against a reference rendered on
// the same machine (its live tolerance, arrays included).
bool student_matches(const LabCases& lab, const GradeCase& c, const LabRun& student, const LabRun& mistake);

}  // namespace gsv
