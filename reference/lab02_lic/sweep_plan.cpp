// Lab 02's sweep plan. Where the field has a formula and the input is the noise, each image of the sweep is measured
// against LIC of the same length along the field's exact streamlines, so that the error is the step's alone: against
// a longer LIC, Euler's and midpoint's errors came out the same. Elsewhere, against the long midpoint LIC.
#include "common/app/sweep_plan.h"
#include "exact_lic_images.h"
#include "sweep_view.h"

#include <memory>

namespace lab02 {
namespace {

class LicSweepPlan final : public gsv::SweepPlan {
public:
    explicit LicSweepPlan(const SweepView& lab) : lab_(lab) {}

    std::vector<std::string> reference() const override { return {"step=midpoint", "length=200"}; }
    std::string reference_name() const override {
        if (exact_applies_) return ExactLicImages::description();
        return "midpoint LIC of length 200, there being no exact LIC of a field from a file or of the photograph: a "
               "longer filter, so the error measures the length as well as the accuracy";
    }
    std::optional<gsv::Image> exact_image(gsv::LabKit& kit, const gsv::Frame& frame) override {
        gsv::check_sweepable(lab_.contrast());
        exact_applies_ = lab_.field_has_formula();
        if (!exact_applies_) return std::nullopt;
        return exact_.image(kit.params(), frame, [&] { return lab_.exact_field(frame); }, [&] { return lab_.noise(frame); });
    }
    // Called at every point of any sweep, the lab's knob or another.
    gsv::SweepMetrics metrics(gsv::LabKit&, const gsv::Frame&) override {
        gsv::check_sweepable(lab_.contrast());
        return {};
    }

private:
    const SweepView& lab_;
    ExactLicImages exact_;
    bool exact_applies_ = false;  // the last sweep point was measured against the exact LIC
};

}  // namespace
}  // namespace lab02

std::unique_ptr<gsv::SweepPlan> gsv::make_lab_sweep_plan(gsv::Lab& lab) {
    return std::make_unique<lab02::LicSweepPlan>(dynamic_cast<const lab02::SweepView&>(lab));
}
