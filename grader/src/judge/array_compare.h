#pragma once
// Comparing the numbers a lab hands in (common/io/data_array.h) with the reference's, the way images are
// compared (common/image/image_compare.h): an element differs when any component is off by more than max_abs, and
// the check passes when no more than a budget of the compared elements differ. A NaN or Inf equals only the
// same (NaN, +Inf or -Inf) on the reference's side: a NaN where the reference is finite is a difference,
// NaN where the reference has NaN too is not.
#include "grader/src/core/array_diff.h"

namespace gsv {

// `actual` null: the lab handed in no array of the expected one's name.
ArrayDiff compare_array(const DataArray* actual, const ExpectedArray& expected, const ArrayTolerance& tolerance);

}  // namespace gsv
