// Lab 03's sweep plan: the images against the flow blended linearly between 256 slices (refined to 512), and the
// sampling columns of time_measure.h. Storage changes what an image costs, not what it shows: the reference is always
// the array's.
#include "common/app/sweep_plan.h"
#include "common/gl/gpu_mesh.h"
#include "common/scene/mesh_data.h"
#include "sweep_view.h"
#include "time_measure.h"

#include <memory>

namespace lab03 {
namespace {

class TextureArraySweepPlan final : public gsv::SweepPlan {
public:
    explicit TextureArraySweepPlan(const SweepView& lab) : lab_(lab) {}

    std::vector<std::string> reference() const override { return {"slices=256", "blend=linear", "storage=array"}; }
    std::vector<std::string> refinement() const override { return {"slices=512", "blend=linear", "storage=array"}; }
    std::string reference_name() const override { return "the flow blended linearly between 256 slices per period"; }

    gsv::SweepMetrics metrics(gsv::LabKit& kit, const gsv::Frame&) override {
        gsv::check_sweepable(lab_.contrast());
        if (!probe_) {
            probe_ = &kit.program("probe", {"gsv/fullscreen.vert", "probe.frag"});
            quad_ = gsv::GpuMesh(gsv::make_fullscreen_quad(), kit.profile());
        }
        return measure_sampling(kit, lab_.slice_params(), *probe_, quad_, lab_.flow(),
                                [&](const gsv::ShaderProgram& p) { lab_.bind_flow(p); });
    }

private:
    const SweepView& lab_;
    const gsv::ShaderLibrary::Entry* probe_ = nullptr;  // what the GPU samples at the playhead (probe.frag)
    gsv::GpuMesh quad_;
};

}  // namespace
}  // namespace lab03

std::unique_ptr<gsv::SweepPlan> gsv::make_lab_sweep_plan(gsv::Lab& lab) {
    return std::make_unique<lab03::TextureArraySweepPlan>(dynamic_cast<const lab03::SweepView&>(lab));
}
