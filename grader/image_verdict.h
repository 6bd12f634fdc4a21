#pragma once
// What one image check found, in the words of the grader's table: passed, not done (the starter's magenta), one flat
// colour, or a wrong image; and a failing case blamed on a TODO it needs ("needs L02-T1 first"). Shared by gsv-grade
// and the browser page's self-check (grader/page_self_check.cpp), so the two tables say the same.
#include "grader/cases.h"
#include "grader/grade_result.h"

#include <cstddef>
#include <vector>

namespace gsv {

// Compares `actual` with `expected` under `tolerance` and fills r.status (Passed, NotDone, BlankImage or WrongImage),
// r.detail, r.points (the case's on a pass) and r.image. Whether a wrong image is another case's golden image copied
// is the grader's question (it can look in the submission), asked after this where it has the means.
ImageDiff judge_image(const Image& actual, const Image& expected, const ImageTolerance& tolerance, const GradeCase& c,
                      CaseResult& r);
// From results[first] on (one lab's): a failing case whose "needs" names a TODO that fails its own cases says so.
void blame_needed_todos(const LabCases& lab, std::vector<CaseResult>& results, std::size_t first);

}  // namespace gsv
