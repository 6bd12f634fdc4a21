#pragma once
// A case's "needs" (grader/src/cases/cases.h): the other TODOs it cannot pass without. Blame lands where the work is.
#include "grader/src/cases/cases.h"
#include "grader/src/judge/grade_result.h"

#include <cstddef>
#include <vector>

namespace gsv {

// Among `results` from `first` on (one lab's rows): a failing case while a TODO it needs fails its own cases becomes
// NeedsFirst, "needs L02-T1 first (its case 'rotation' fails); here: ...". Passes, build errors and the kit's own
// faults stay as they are.
void blame_needed_todos(const LabCases& lab, std::vector<CaseResult>& results, std::size_t first);

}  // namespace gsv
