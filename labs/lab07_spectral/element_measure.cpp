#include "element_measure.h"

#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/app/sweep_metrics.h"
#include "common/timing/timing.h"

#include <algorithm>
#include <cmath>

namespace lab07 {
gsv::SweepMetrics measure_elements(gsv::LabKit& kit, const ElementData& data, const MeasurePrograms& programs,
                                   const gsv::Transforms& transforms, int width, int height) {
    gsv::Framebuffer target(width, height, gsv::ColorFormat::RGBA32F, false);
    auto draw_with = [&](const gsv::ShaderLibrary::Entry& entry) {
        target.bind();
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        const gsv::ShaderProgram& program = kit.use(entry);
        kit.set_transforms(program, transforms);
        data.bind(program);
        program.set("uRangeMin", data.min_value);
        program.set("uRangeMax", data.max_value);
        data.patches.draw();
    };
    draw_with(*programs.probe);
    const gsv::ImageF probe = target.read_rgba32f();

    double worst = 0, sum2 = 0, worst_float = 0;
    long count = 0;
    for (int y = 0; y < height; y += 2)
        for (int x = 0; x < width; x += 2) {
            const float* px = probe.at(x, y);
            if (px[3] < 0.5f) continue;
            const int element = static_cast<int>(std::lround(px[3])) - 1;
            const double xi = px[1], eta = px[2];
            const double exact = gsv::spectral_field(data.field, data.mesh.position(element, xi, eta), data.time);
            const double in_double = gsv::evaluate_element(data.values, data.nodes, data.weights, element, xi, eta);
            const double e = std::abs(px[0] - exact);
            worst = std::max(worst, e);
            sum2 += e * e;
            worst_float = std::max(worst_float, std::abs(px[0] - in_double));
            ++count;
        }
    // The two shaders timed in turns, so that whatever else the machine does falls on both alike.
    const gsv::InterleavedTimes times = gsv::time_interleaved(
        {{nullptr, [&] { draw_with(*programs.color); }}, {nullptr, [&] { draw_with(*programs.corners); }}}, gsv::kCompareWarmup,
        gsv::kCompareFrames, gsv::kCompareRounds);
    gsv::SweepMetrics m{{"err_max", worst}, {"err_rms", count ? std::sqrt(sum2 / count) : 0.0}, {"float_err_max", worst_float}};
    gsv::add_time(m, "drawn_ms", times.stats[0]);
    gsv::add_time(m, "corner_ms", times.stats[1]);
    gsv::add_ratio(m, "rate_vs_corners", times.ratio(1, 0));
    m.emplace_back("basis_bytes", static_cast<double>(data.basis_bytes()));
    m.emplace_back("value_bytes", static_cast<double>(data.value_texture.bytes()));
    return m;
}

}  // namespace lab07
