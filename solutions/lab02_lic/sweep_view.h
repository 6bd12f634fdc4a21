#pragma once
// What lab 02 shows, read-only, to the sweep plan that measures it (the instructor's reference/lab02_lic/): enough
// to draw the same LIC along the field's exact streamlines. The lab draws nothing for it.
#include "common/app/app.h"
#include "support/flow/flow_field.h"
#include "support/flow/lic_contrast.h"

#include <vector>

namespace lab02 {

class SweepView {
public:
    virtual ~SweepView() = default;
    virtual gsv::LicContrast contrast() const = 0;
    // Whether the field has a formula and LIC smears the white noise: where an exact LIC can be drawn.
    virtual bool field_has_formula() const = 0;
    // The field the flow texture samples, everywhere (where it has a formula), as the observer sees it.
    virtual gsv::VelocityAt exact_field(const gsv::Frame& frame) const = 0;
    // The white noise the input texture holds.
    virtual std::vector<float> noise(const gsv::Frame& frame) const = 0;
};

}  // namespace lab02
