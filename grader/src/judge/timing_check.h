#pragma once
// The timing half of a case: its frame time against the reference's, by the grader's clock, for frames only their
// work can produce. Student and reference rounds alternate; in each, every timed frame answers a challenge of settings
// drawn afresh (the case's "timing": {"vary": ...}), and is checked against the reference's frame drawn with the same
// settings. The ratio is the median of the student's rounds over the reference's; one near or over the band is
// measured again before it counts.
#include "grader/src/cases/cases.h"
#include "grader/src/core/grade_result.h"
#include "grader/src/run/lab_run.h"
#include "grader/src/run/process.h"

namespace gsv {

// The timing row of case `c`, whose image row `image` passed: passed within the band (with its timing points), too
// slow over it, or the status of a round that failed or handed in a frame that is not the one asked for.
CaseResult check_timing(const LabCases& lab, const GradeCase& c, const CaseResult& image, const LabRunner& student,
                        const ProcessLimits& student_limits, const LabRunner& reference, const ProcessLimits& reference_limits);

}  // namespace gsv
