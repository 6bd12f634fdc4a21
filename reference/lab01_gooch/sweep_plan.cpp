// Lab 01's sweep plan: each shading rate and mesh resolution against the exact sphere, ray-cast at each pixel and lit
// with its exact normal (the lab's exact_sphere.frag), where the sphere is what the lab draws; elsewhere against the
// finest mesh lit per fragment. Plotted: the error of what each rate lights a pixel with (sphere_measure.h); the
// image RMSE adds the outline's error.
#include "common/app/sweep_plan.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/gl/gpu_mesh.h"
#include "common/scene/mesh_data.h"
#include "sphere_measure.h"
#include "sweep_view.h"

#include <glm/glm.hpp>

#include <memory>

namespace lab01 {
namespace {

class GoochSweepPlan final : public gsv::SweepPlan {
public:
    explicit GoochSweepPlan(SweepView& lab) : lab_(lab) {}

    std::vector<std::string> reference() const override { return {"shading_rate=fragment", "mesh_resolution=1024"}; }
    std::string error_column() const override { return "shading_err_mean"; }
    std::string reference_name() const override {
        return "the exact sphere, ray-cast at each pixel and lit with its exact normal (exact_sphere.frag)";
    }

    std::optional<gsv::Image> exact_image(gsv::LabKit& kit, const gsv::Frame& frame) override {
        if (!lab_.exact_sphere_applies()) return std::nullopt;
        gsv::Framebuffer target(frame.width, frame.height, gsv::ColorFormat::RGBA8);
        target.bind();
        draw_exact_sphere(kit, frame, lab_.background());
        return target.read_rgba8();
    }

    // What each rate lights a pixel with against the exact sphere's shading there; per fragment, also the normal
    // it lights with against the exact normal (per vertex lights with no interpolated normal).
    gsv::SweepMetrics metrics(gsv::LabKit& kit, const gsv::Frame& frame) override {
        if (!lab_.exact_sphere_applies()) return {};
        const gsv::ImageF lit = float_image(frame, [&] { lab_.draw(kit, frame, lab_.shade_program(), glm::vec4(0.0f)); });
        const gsv::ImageF exact = float_image(frame, [&] { draw_exact_sphere(kit, frame, glm::vec4(0.0f)); });
        gsv::SweepMetrics metrics = shading_error(lit, exact);
        if (lab_.lights_each_fragment()) {
            const gsv::ImageF angles =
                float_image(frame, [&] { lab_.draw(kit, frame, programs(kit).normal_error, glm::vec4(0.0f)); });
            for (auto& m : normal_error(angles)) metrics.push_back(m);
        }
        return metrics;
    }

private:
    struct Programs {
        const gsv::ShaderLibrary::Entry& exact_sphere;
        const gsv::ShaderLibrary::Entry& normal_error;
    };
    // Made when first measured: a sweep's, never the lab's frame.
    Programs programs(gsv::LabKit& kit) {
        if (!exact_sphere_) {
            exact_sphere_ = &kit.program("exact_sphere", {"gsv/fullscreen.vert", "exact_sphere.frag"});
            normal_error_ = &kit.program("normal_error", {"shade.vert", "normal_error.frag"});
            quad_ = gsv::GpuMesh(gsv::make_fullscreen_quad(), kit.profile());
        }
        return {*exact_sphere_, *normal_error_};
    }

    void draw_exact_sphere(gsv::LabKit& kit, const gsv::Frame& frame, glm::vec4 background) {
        const gsv::ShaderLibrary::Entry& entry = programs(kit).exact_sphere;
        glClearColor(background.r, background.g, background.b, background.a);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        const gsv::ShaderProgram& program = kit.use(entry);
        const gsv::Transforms t = lab_.set_view(kit, program, frame);
        program.set("uInverseProjection", glm::inverse(t.projection));
        glDisable(GL_DEPTH_TEST);
        quad_.draw();
    }

    // A pass drawn into a float target whose background has alpha 0, so covered pixels can be told apart.
    template <class Draw>
    static gsv::ImageF float_image(const gsv::Frame& frame, const Draw& draw) {
        gsv::Framebuffer target(frame.width, frame.height, gsv::ColorFormat::RGBA32F);
        target.bind();
        draw();
        return target.read_rgba32f();
    }

    SweepView& lab_;
    const gsv::ShaderLibrary::Entry* exact_sphere_ = nullptr;
    const gsv::ShaderLibrary::Entry* normal_error_ = nullptr;
    gsv::GpuMesh quad_;
};

}  // namespace
}  // namespace lab01

std::unique_ptr<gsv::SweepPlan> gsv::make_lab_sweep_plan(gsv::Lab& lab) {
    return std::make_unique<lab01::GoochSweepPlan>(dynamic_cast<lab01::SweepView&>(lab));
}
