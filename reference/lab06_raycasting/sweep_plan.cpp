// Lab 06's sweep plan: each compositing's images against the same compositing at 16 samples per voxel (refined to
// 32), isosurface hits against the exact Marschner-Lobb crossing (hit_measure.h), and with compare_shaders=on the
// ray caster timed through the other shaders (ray_measure.h).
#include "common/app/sweep_plan.h"
#include "hit_measure.h"
#include "ray_measure.h"
#include "sweep_view.h"

#include <memory>

namespace lab06 {
namespace {

class RaycastSweepPlan final : public gsv::SweepPlan {
public:
    explicit RaycastSweepPlan(SweepView& lab) : lab_(lab) {}

    std::vector<std::string> reference() const override { return {"samples_per_voxel=16"}; }
    std::vector<std::string> refinement() const override { return {"samples_per_voxel=32"}; }
    std::string reference_name() const override {
        return "images: the same compositing at 16 samples per voxel; isosurface hits (iso_err): the exact crossing of the "
               "Marschner-Lobb signal along each ray, in double";
    }
    bool reference_per_series() const override { return true; }

    gsv::SweepMetrics metrics(gsv::LabKit& kit, const gsv::Frame&) override {
        RayTraversal* raycaster = lab_.raycaster();
        if (!raycaster) return {};
        gsv::SweepMetrics metrics = measure_hits(kit, *raycaster, lab_.frame_view());
        if (lab_.compare_shaders()) {
            const gsv::SweepMetrics times = compare_shaders(*raycaster);
            metrics.insert(metrics.end(), times.begin(), times.end());
        }
        return metrics;
    }

private:
    SweepView& lab_;
};

}  // namespace
}  // namespace lab06

std::unique_ptr<gsv::SweepPlan> gsv::make_lab_sweep_plan(gsv::Lab& lab) {
    return std::make_unique<lab06::RaycastSweepPlan>(dynamic_cast<lab06::SweepView&>(lab));
}
