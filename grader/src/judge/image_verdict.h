#pragma once
// What one image check found, in the words of the grader's table: passed, not done (the starter's magenta), one flat
// colour, or a wrong image. Shared by gsv-grade (judge/image_check) and the browser page's self-check
// (app/page_self_check.cpp), so the two tables say the same.
#include "common/image/image.h"
#include "common/image/image_compare.h"
#include "grader/src/cases/cases.h"
#include "grader/src/core/grade_result.h"

namespace gsv {

// Compares `actual` with `expected` under `tolerance` and fills r.status (Passed, NotDone, BlankImage or WrongImage),
// r.detail, r.points (the case's on a pass) and r.image. Whether a wrong image is another case's golden image copied
// is the grader's question (it can look in the submission), asked after this where it has the means.
// Whether judge_image would pass `actual` against `expected`: within the tolerance and not moved as a whole. Cheaper
// (no SSIM, no PSNR; the offset only of a picture within the tolerance), for the many comparisons of a diagnosis.
bool image_passes(const Image& actual, const Image& expected, const ImageTolerance& tolerance);

ImageDiff judge_image(const Image& actual, const Image& expected, const ImageTolerance& tolerance, const GradeCase& c,
                      CaseResult& r);

}  // namespace gsv
