#pragma once
// Lab 07's sweep columns: what the per-fragment evaluation costs against drawing from the corners only, and the
// memory the basis and the values take. (Its error against the analytic field and against the same polynomial in
// double is the instructor's measurement: reference/lab07_spectral/.)
#include "common/app/sweep_plan.h"
#include "common/gl/framebuffer.h"
#include "common/scene/transforms.h"
#include "common/shader/shader_library.h"
#include "element_data.h"

namespace lab07 {

struct MeasurePrograms {
    const gsv::ShaderLibrary::Entry* color = nullptr;   // what the lab draws
    const gsv::ShaderLibrary::Entry* corners = nullptr;  // the same from the corner values only
    const gsv::ShaderLibrary::Entry* probe = nullptr;    // value, xi, eta, element + 1
};

// The elements drawn with `entry` into `target`, cleared to 0 first, with the lab's range.
void draw_elements(gsv::LabKit& kit, const ElementData& data, const gsv::ShaderLibrary::Entry& entry,
                   const gsv::Transforms& transforms, const gsv::Framebuffer& target);

// drawn_ms (what the lab draws: with evaluation=full the per-fragment polynomial), corner_ms (the corner values
// only; both glFinish, median of 5) and rate_vs_corners = corner_ms / drawn_ms, the frame rate as a fraction of
// corner-only drawing (the seed's measure); basis_bytes and value_bytes.
gsv::SweepMetrics measure_costs(gsv::LabKit& kit, const ElementData& data, const MeasurePrograms& programs,
                                const gsv::Transforms& transforms, int width, int height);

}  // namespace lab07
