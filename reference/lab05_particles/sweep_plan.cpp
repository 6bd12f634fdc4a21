// Lab 05's sweep plan: the images against RK4 at the smallest step, the particles' positions against the instructor's
// CPU integrators in double (particle_measure.h). The plotted error is the positions': the images' RMSE says little,
// particles restarting at times that depend on the step.
#include "common/app/sweep_plan.h"
#include "particle_measure.h"
#include "sweep_view.h"

#include <memory>

namespace lab05 {
namespace {

class ParticleSweepPlan final : public gsv::SweepPlan {
public:
    explicit ParticleSweepPlan(SweepView& lab) : lab_(lab) {}

    std::vector<std::string> reference() const override { return {"time_step=0.00625", "integrator=rk4"}; }
    std::string error_column() const override { return "pos_err_rms"; }
    std::string reference_name() const override {
        return "positions (pos_err): the same particles in double precision, RK4 in substeps of at most 0.001, far below "
               "float32's error; images: RK4 at the smallest step";
    }

    gsv::SweepMetrics metrics(gsv::LabKit& kit, const gsv::Frame&) override {
        gsv::SweepMetrics metrics = measure(lab_.stepper(kit), lab_.initial_particles(), lab_.steps_done());
        lab_.buffers_restarted();
        return metrics;
    }

private:
    SweepView& lab_;
};

}  // namespace
}  // namespace lab05

std::unique_ptr<gsv::SweepPlan> gsv::make_lab_sweep_plan(gsv::Lab& lab) {
    return std::make_unique<lab05::ParticleSweepPlan>(dynamic_cast<lab05::SweepView&>(lab));
}
