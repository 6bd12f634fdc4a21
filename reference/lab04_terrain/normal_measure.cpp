#include "normal_measure.h"

#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/shader/shader_program.h"
#include "reference/terrain/terrain_normal.h"

#include <algorithm>
#include <cmath>

namespace lab04 {
namespace {

constexpr double kRadToDeg = 57.29577951308232;

// The CPU's frame has z along the rows (north); the lab's world has z south.
glm::dvec3 to_world(glm::dvec3 n) { return {n.x, n.y, -n.z}; }

// The height at fractional sample index (i, j), interpolated like GL_LINEAR with CLAMP_TO_EDGE, in double.
double height_at(const gsv::HeightField& f, double i, double j) {
    const auto lerp_axis = [](double t, int n, int& a, int& b) {
        t = std::clamp(t, 0.0, static_cast<double>(n - 1));
        a = static_cast<int>(std::floor(t));
        b = std::min(a + 1, n - 1);
        return t - a;
    };
    int x0, x1, y0, y1;
    const double fx = lerp_axis(i, f.width, x0, x1), fy = lerp_axis(j, f.height, y0, y1);
    const double bottom = f.at(x0, y0) + fx * (f.at(x1, y0) - f.at(x0, y0));
    const double top = f.at(x0, y1) + fx * (f.at(x1, y1) - f.at(x0, y1));
    return bottom + fy * (top - bottom);
}

// normal.glsl's terrainNormal at sample (x, y) in double precision, for any step (the CPU's
// finite_difference_normal takes whole samples only), in the lab's world (z south).
glm::dvec3 shader_normal(const gsv::HeightField& f, int x, int y, double e, double delta) {
    const double lo_x = std::max(x - delta, 0.0), hi_x = std::min(x + delta, f.width - 1.0);
    const double lo_y = std::max(y - delta, 0.0), hi_y = std::min(y + delta, f.height - 1.0);
    const double span_x = (hi_x - lo_x) * f.dx_m, span_y = (hi_y - lo_y) * f.dy_m;
    const double slope_x = span_x > 0 ? (height_at(f, hi_x, y) - height_at(f, lo_x, y)) / span_x : 0.0;
    const double slope_y = span_y > 0 ? (height_at(f, x, hi_y) - height_at(f, x, lo_y)) / span_y : 0.0;
    return glm::normalize(glm::dvec3(-e * slope_x, 1.0, e * slope_y));
}

}  // namespace

gsv::SweepMetrics measure_normals(gsv::LabKit& kit, const Terrain& terrain, const gsv::ShaderLibrary::Entry& probe,
                                  const gsv::GpuMesh& quad, const std::function<void(const gsv::ShaderProgram&)>& set_uniforms) {
    const auto& p = kit.params();
    const gsv::HeightField& f = terrain.field;
    gsv::Framebuffer target(f.width, f.height, gsv::ColorFormat::RGBA32F, false);
    target.bind();
    glDisable(GL_DEPTH_TEST);
    const gsv::ShaderProgram& program = kit.use(probe);
    set_uniforms(program);
    quad.draw();
    const gsv::ImageF normals = target.read_rgba32f();

    const double e = p.get_float("exaggeration");
    const double delta = p.get_float("delta");
    double sum = 0, worst = 0, worst_vs_cpu = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            const float* texel = normals.at(x, f.height - 1 - y);  // readback rows run top down
            const glm::dvec3 gpu(texel[0], texel[1], texel[2]);
            const glm::dvec3 truth = terrain.procedural
                                         ? to_world(gsv::exact_normal(*terrain.procedural, gsv::sample_position(f, x, y), e))
                                         : to_world(gsv::finite_difference_normal(f, x, y, e, 1));
            const double angle = gsv::normal_angle(gpu, truth) * kRadToDeg;
            sum += angle;
            worst = std::max(worst, angle);
            worst_vs_cpu = std::max(worst_vs_cpu, gsv::normal_angle(gpu, shader_normal(f, x, y, e, delta)) * kRadToDeg);
        }
    return {{"normal_err_mean_deg", sum / (static_cast<double>(f.width) * f.height)},
            {"normal_err_max_deg", worst},
            {"gpu_vs_cpu_max_deg", worst_vs_cpu}};
}

}  // namespace lab04
