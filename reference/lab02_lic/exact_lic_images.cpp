#include "exact_lic_images.h"

namespace lab02 {

const gsv::Image& ExactLicImages::image(const gsv::Params& p, const gsv::Frame& frame,
                                        const std::function<gsv::VelocityAt()>& field,
                                        const std::function<std::vector<float>()>& noise) {
    exact_.update(p, [&] {
        return gsv::ExactLic(field(), noise(), frame.width, frame.height, {p.get_bool("normalized")});
    }, frame.width, frame.height);
    return exact_->image(p.get_int("length"));
}

std::string ExactLicImages::description() {
    return "LIC of the same length along the exact streamlines of the analytic field: RK4 in double on the CPU, " +
           std::to_string(gsv::kLicSubsteps) + " substeps per step, bilinear noise lookups";
}

}  // namespace lab02
