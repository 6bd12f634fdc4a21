#include "sphere_measure.h"

#include <algorithm>
#include <cmath>

namespace lab01 {

gsv::SweepMetrics shading_error(const gsv::ImageF& lit, const gsv::ImageF& exact) {
    double sum = 0, worst = 0;
    long covered = 0;
    for (int y = 0; y < lit.height; ++y)
        for (int x = 0; x < lit.width; ++x) {
            const float* a = lit.at(x, y);
            const float* b = exact.at(x, y);
            if (a[3] == 0.0f || b[3] == 0.0f) continue;
            double levels = 0;
            for (int c = 0; c < 3; ++c)
                levels = std::max(levels, 255.0 * std::abs(std::clamp<double>(a[c], 0, 1) - std::clamp<double>(b[c], 0, 1)));
            sum += levels;
            worst = std::max(worst, levels);
            ++covered;
        }
    return {{"shading_err_mean", covered ? sum / static_cast<double>(covered) : 0.0}, {"shading_err_max", worst}};
}

gsv::SweepMetrics normal_error(const gsv::ImageF& angles) {
    double sum = 0, worst = 0;
    long covered = 0;
    for (int y = 0; y < angles.height; ++y)
        for (int x = 0; x < angles.width; ++x) {
            const float* texel = angles.at(x, y);
            if (texel[3] == 0.0f) continue;
            sum += texel[0];
            worst = std::max(worst, static_cast<double>(texel[0]));
            ++covered;
        }
    return {{"normal_err_mean_deg", covered ? sum / static_cast<double>(covered) : 0.0}, {"normal_err_max_deg", worst}};
}

}  // namespace lab01
