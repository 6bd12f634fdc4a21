#pragma once
// What makes a LIC worth projecting, declared alike by every LIC lab (02, 03): an observer moving along +x, in whose
// frame the vortex street's drifting vortices show, and a tone curve after the LIC (support/flow/lic_contrast.h).
#include "common/params/params.h"
#include "support/flow/lic_contrast.h"

namespace gsv {

struct LicViewParams {
    Param<float> observer_velocity;  // a fraction of `speed`, subtracted from the flow's x velocity
    EnumParam<LicContrast> contrast;
};

// Declares observer_velocity and contrast; the lab keeps the handles.
LicViewParams add_lic_view_params(Params& params);

}  // namespace gsv
