// Lab 07's sweep plan: the images against the highest degree on GLL nodes, the values against the instructor's CPU
// evaluation (value_measure.h), and what the evaluation costs (element_measure.h).
#include "common/app/sweep_plan.h"
#include "element_measure.h"
#include "sweep_view.h"
#include "value_measure.h"

#include <memory>

namespace lab07 {
namespace {

class SpectralSweepPlan final : public gsv::SweepPlan {
public:
    explicit SpectralSweepPlan(const SweepView& lab) : lab_(lab) {}

    std::vector<std::string> reference() const override { return {"degree=16", "node_set=gll"}; }
    std::string error_column() const override { return "err_max"; }
    std::string reference_name() const override {
        return "values (err): the exact field in double at each pixel's point of the element; images: the highest "
               "degree on GLL nodes";
    }

    gsv::SweepMetrics metrics(gsv::LabKit& kit, const gsv::Frame& frame) override {
        const gsv::Transforms t = lab_.transforms(frame);
        gsv::SweepMetrics metrics =
            measure_values(kit, lab_.element_data(), lab_.measure_programs(), t, frame.width, frame.height);
        const gsv::SweepMetrics costs =
            measure_costs(kit, lab_.element_data(), lab_.measure_programs(), t, frame.width, frame.height);
        metrics.insert(metrics.end(), costs.begin(), costs.end());
        return metrics;
    }

private:
    const SweepView& lab_;
};

}  // namespace
}  // namespace lab07

std::unique_ptr<gsv::SweepPlan> gsv::make_lab_sweep_plan(gsv::Lab& lab) {
    return std::make_unique<lab07::SpectralSweepPlan>(dynamic_cast<const lab07::SweepView&>(lab));
}
