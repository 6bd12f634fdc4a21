// Lab 04's sweep plan: the images against the finest step (delta 1), the shader's normals against the instructor's
// CPU normals (normal_measure.h). The plotted error is the normals' against the truth where a formula gives it; real
// data have no truer normals than their own samples' finest differences.
#include "common/app/sweep_plan.h"
#include "common/gl/gpu_mesh.h"
#include "common/scene/mesh_data.h"
#include "normal_measure.h"
#include "sweep_view.h"

#include <memory>

namespace lab04 {
namespace {

class TerrainSweepPlan final : public gsv::SweepPlan {
public:
    explicit TerrainSweepPlan(const SweepView& lab) : lab_(lab) {}

    std::vector<std::string> reference() const override { return {"delta=1"}; }
    std::string error_column() const override { return "normal_err_mean_deg"; }
    std::string reference_name() const override {
        return lab_.terrain().procedural
                   ? "normals: the analytic terrain's exact normals, in double; images: the image at the finest step"
                   : "normals: central differences one sample apart on the full-resolution data, in double (the finest "
                     "the samples allow, not the true ground); images: the image at that step";
    }

    gsv::SweepMetrics metrics(gsv::LabKit& kit, const gsv::Frame&) override {
        if (!probe_) {
            probe_ = &kit.program("normal_probe", {"gsv/fullscreen.vert", "normal_probe.frag"});
            quad_ = gsv::GpuMesh(gsv::make_fullscreen_quad(), kit.profile());
        }
        return measure_normals(kit, lab_.terrain(), *probe_, quad_,
                               [&](const gsv::ShaderProgram& program) { lab_.set_terrain_uniforms(program); });
    }

private:
    const SweepView& lab_;
    const gsv::ShaderLibrary::Entry* probe_ = nullptr;  // the shader's normals, one fragment per sample
    gsv::GpuMesh quad_;
};

}  // namespace
}  // namespace lab04

std::unique_ptr<gsv::SweepPlan> gsv::make_lab_sweep_plan(gsv::Lab& lab) {
    return std::make_unique<lab04::TerrainSweepPlan>(dynamic_cast<const lab04::SweepView&>(lab));
}
