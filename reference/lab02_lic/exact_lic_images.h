#pragma once
// Lab 02's sweep reference where the field has a formula: LIC of the same length along the field's exact
// streamlines (reference/flow/lic_reference.h), the instructor's yardstick of the lab's LIC loop (L02-T1 to
// L02-T5), for its sweep plan (sweep_plan.cpp). Compiled into lab02_solution only.
#include "common/app/app.h"
#include "common/params/change_tracker.h"
#include "reference/flow/lic_reference.h"

#include <functional>
#include <string>
#include <vector>

namespace lab02 {

class ExactLicImages {
public:
    // The exact LIC of `length` (the current parameter) steps each way. `field` and `noise` are asked for only
    // when a parameter they read changed, so the streamlines walked for one length serve the longer ones.
    const gsv::Image& image(const gsv::Params& p, const gsv::Frame& frame, const std::function<gsv::VelocityAt()>& field,
                            const std::function<std::vector<float>()>& noise);
    // The reference in words, for the sweep's table and plots.
    static std::string description();

private:
    gsv::Tracked<gsv::ExactLic> exact_;
};

}  // namespace lab02
