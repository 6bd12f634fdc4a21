#pragma once
// Lab 07's error columns, the instructor's: the per-fragment evaluation against the analytic field and against
// the same polynomial evaluated in double on the CPU (reference/spectral/lagrange_basis.h, the yardstick of L07-T1
// and L07-T2). Compiled into lab07_solution only; the student's sweep has the images, times and bytes alone.
#include "common/app/app.h"
#include "element_measure.h"

namespace lab07 {

// err_max and err_rms: against the analytic field at every second pixel's (element, xi, eta) as the GPU
// interpolated them; float_err_max: against evaluate_element in double at the same (xi, eta), the cost of
// float32 alone.
gsv::SweepMetrics measure_values(gsv::LabKit& kit, const ElementData& data, const MeasurePrograms& programs,
                                 const gsv::Transforms& transforms, int width, int height);

}  // namespace lab07
