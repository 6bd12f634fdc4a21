#include "support/flow/lic_view_params.h"

#include "support/flow/lic_contrast.h"

namespace gsv {

void add_lic_view_params(Params& p) {
    p.add_float("observer_velocity", 0, -1, 1,
                "the observer's velocity along +x, a fraction of `speed`, subtracted from the flow: a frame that "
                "moves with the vortex street's vortices shows them")
        .with_step(0.01);
    p.add_choice("contrast", "off", lic_contrast_names(),
                 "a tone curve after the LIC: a stretch of the 0.5-99.5 percentiles to black and white, or histogram "
                 "equalisation");
}

}  // namespace gsv
