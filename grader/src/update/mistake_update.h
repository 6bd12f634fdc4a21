#pragma once
// Writes the known mistakes a student's copy ships (common/app/known_mistake_pictures.h): for each lab the options
// choose, every known mistake of tests/mutants/<lab>.json and every shader TODO left as the starter has it, rendered
// on every public case by the reference solution with the mistake made (grader/src/grade/mistake_pictures.h), judged
// against the committed goldens as a self-check judges, and kept (as a signature) where it fails the case. Out of the
// grading path: `gsv-grade --update-mistakes`, after the goldens. A row per lab, passed when its file was written.
#include "grader/src/grade/grade.h"

namespace gsv {

GradeReport update_mistake_pictures(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress = {});

}  // namespace gsv
