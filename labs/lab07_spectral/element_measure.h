#pragma once
// Lab 07's sweep columns: the per-fragment evaluation against the analytic field and against the same
// polynomial evaluated in double on the CPU, what it costs against drawing from the corners only, and the
// memory the basis and the values take.
#include "common/app/app.h"
#include "common/scene/transforms.h"
#include "common/shader/shader_library.h"
#include "element_data.h"

namespace lab07 {

struct MeasurePrograms {
    const gsv::ShaderLibrary::Entry* color = nullptr;   // what the lab draws
    const gsv::ShaderLibrary::Entry* corners = nullptr;  // the same from the corner values only
    const gsv::ShaderLibrary::Entry* probe = nullptr;    // value, xi, eta, element + 1
};

// err_max and err_rms: against the analytic field at every second pixel's (element, xi, eta) as the GPU
// interpolated them; float_err_max: against evaluate_element in double at the same (xi, eta), the cost of
// float32 alone; drawn_ms (what the lab draws: with evaluation=full the per-fragment polynomial), corner_ms
// (the corner values only; both glFinish, median of 5) and rate_vs_corners = corner_ms / drawn_ms, the frame
// rate as a fraction of corner-only drawing (the seed's measure); basis_bytes and value_bytes.
gsv::SweepMetrics measure_elements(gsv::LabKit& kit, const ElementData& data, const MeasurePrograms& programs,
                                   const gsv::Transforms& transforms, int width, int height);

}  // namespace lab07
