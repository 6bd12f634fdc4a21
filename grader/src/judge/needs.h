#pragma once
// A case's "needs" (grader/src/cases/cases.h): the other TODOs it cannot pass without. Blame lands where the work is.
#include "grader/src/cases/cases.h"
#include "grader/src/core/grade_result.h"

#include <cstddef>
#include <vector>

namespace gsv {

// Whether a status says only how the picture or numbers came out (wrong image, blank image, not done, wrong data, GPU
// margin), which a needed TODO's failure can explain; every other status (an integrity or process status: copied
// image, refused, crash, timeout, memory, wrote too much, NaN, ...) says what the lab did, and stands.
bool is_quality_status(CaseStatus status);

// Among `results` from `first` on (one lab's rows). A TODO fails on its own where one of its cases fails while no TODO
// that case needs fails: such a TODO is a root. A failing case whose needed TODOs fail is blamed on the roots they
// come down to (through needed TODOs that only fail for their own needs; never the case's own TODO, never in a
// circle): a quality status becomes NeedsFirst, "needs L02-T1 first (its case 'rotation' fails); here: ...", and any
// other status stands with the need added to its detail. Where the need leads to no root (TODOs that need each other
// and fail only for each other), the case keeps its own status. Passes, build errors and the kit's faults stay as they
// are. A failure a known mistake explains (CaseResult::mistake_todo, grader/src/diagnose/) is put on the mistake's TODO,
// which is then a root: its status stands and its detail names the mistake.
// Where a student part way through starts: the first TODO (in the case file's order) whose cases do not all pass and
// that has a public case needing no other TODO, as "L01-T1 (its case 'eye-normals' needs no other TODO)"; empty
// where every case passes or no such TODO is left.
std::string way_in(const LabCases& lab, const std::vector<CaseResult>& results, std::size_t first);

void blame_needed_todos(const LabCases& lab, std::vector<CaseResult>& results, std::size_t first);

}  // namespace gsv
