#pragma once
// What lab 03 shows, read-only, to the sweep plan that measures it (the instructor's reference/lab03_texture_arrays/):
// the slices as the lab made and bound them, so the plan can sample what the GPU samples.
#include "common/shader/shader_program.h"
#include "support/flow/flow_field.h"
#include "support/flow/lic_contrast.h"
#include "time_flow.h"

namespace lab03 {

class SweepView {
public:
    virtual ~SweepView() = default;
    virtual gsv::LicContrast contrast() const = 0;
    virtual const SliceParams& slice_params() const = 0;
    // The slices of the last frame drawn, and how the lab binds them to a program (its storage's uniforms).
    virtual const gsv::FlowSequence& flow() const = 0;
    virtual void bind_flow(const gsv::ShaderProgram& program) const = 0;
};

}  // namespace lab03
