#include "support/flow/lic_view_params.h"

namespace gsv {

LicViewParams add_lic_view_params(Params& p) {
    LicViewParams view;
    view.observer_velocity = p.add_float("observer_velocity", 0, -1, 1,
                                         "the observer's velocity along +x, a fraction of `speed`, subtracted from the "
                                         "flow: a frame that moves with the vortex street's vortices shows them")
                                 .with_step(0.01);
    view.contrast = p.add_enum("contrast", LicContrast::Off, kLicContrastNames,
                               "a tone curve after the LIC: a stretch of the 0.5-99.5 percentiles to black and white, or "
                               "histogram equalisation");
    return view;
}

}  // namespace gsv
