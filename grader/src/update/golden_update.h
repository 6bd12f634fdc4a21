#pragma once
// Rewrites the committed goldens, out of the grading path: grader/golden/<lab>/<case>.png of every public case the
// options choose, rendered by the reference solution, and for a lab that hands in arrays a sampled golden of each
// array the case checks (grader/src/golden/array_golden.h). No student code is graded; a row per case, passed when
// its goldens were written ("wrote ..."), else the reference's failure.
#include "grader/src/grade/grade.h"

namespace gsv {

// The options choose the kit, its build, the output folder and the labs and cases as for grade(); the goldens are
// core-profile images. Throws gsv::Error on what stops the run as a whole, as grade() does.
GradeReport update_goldens(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress = {});

}  // namespace gsv
