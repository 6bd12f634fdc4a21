#include "value_measure.h"

#include "reference/spectral/lagrange_basis.h"

#include <algorithm>
#include <cmath>

namespace lab07 {

gsv::SweepMetrics measure_values(gsv::LabKit& kit, const ElementData& data, const MeasurePrograms& programs,
                                 const gsv::Transforms& transforms, int width, int height) {
    gsv::Framebuffer target(width, height, gsv::ColorFormat::RGBA32F, false);
    draw_elements(kit, data, *programs.probe, transforms, target);
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
    return {{"err_max", worst}, {"err_rms", count ? std::sqrt(sum2 / count) : 0.0}, {"float_err_max", worst_float}};
}

}  // namespace lab07
