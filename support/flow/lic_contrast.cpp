#include "support/flow/lic_contrast.h"

#include "common/core/enum_names.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace gsv {
namespace {

// The value below which `share` of the sorted values lie, linear between neighbours.
float percentile(const std::vector<float>& sorted, double share) {
    const double position = share * static_cast<double>(sorted.size() - 1);
    const std::size_t below = static_cast<std::size_t>(std::floor(position));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    const double w = position - static_cast<double>(below);
    return static_cast<float>(sorted[below] + w * (static_cast<double>(sorted[above]) - sorted[below]));
}

// Each bin edge low + i (high - low) / bins mapped to the share of values below it: the cumulative histogram,
// which spreads the values evenly over [0, 1]. Linear within a bin, as if its values were spread evenly over it.
std::vector<float> cumulative_shares(const std::vector<float>& sorted, float low, float high, int bins) {
    std::vector<float> edges(static_cast<std::size_t>(bins) + 1);
    const double n = static_cast<double>(sorted.size());
    for (int i = 0; i <= bins; ++i) {
        const double edge = low + (static_cast<double>(high) - low) * i / bins;
        // Values equal to the top edge count as below it, so the last edge maps to exactly 1.
        const auto end = i == bins ? sorted.end() : std::lower_bound(sorted.begin(), sorted.end(), edge);
        edges[static_cast<std::size_t>(i)] = static_cast<float>(static_cast<double>(end - sorted.begin()) / n);
    }
    return edges;
}

}  // namespace

LicContrast lic_contrast_from_name(const std::string& name) { return parse_enum(kLicContrastNames, "contrast", name); }

float ToneCurve::operator()(float grey) const {
    if (identity() || std::isnan(grey)) return grey;
    const double position = (static_cast<double>(grey) - low) / (static_cast<double>(high) - low) *
                            static_cast<double>(values.size() - 1);
    if (!(position > 0)) return values.front();
    if (position >= static_cast<double>(values.size() - 1)) return values.back();
    const std::size_t i = static_cast<std::size_t>(position);
    const double w = position - static_cast<double>(i);
    return static_cast<float>(values[i] + w * (static_cast<double>(values[i + 1]) - values[i]));
}

ToneCurve make_tone_curve(const std::vector<float>& grey, LicContrast contrast) {
    ToneCurve identity;
    if (contrast == LicContrast::Off) return identity;
    std::vector<float> sorted;
    sorted.reserve(grey.size());
    for (float g : grey)
        if (std::isfinite(g)) sorted.push_back(g);
    std::sort(sorted.begin(), sorted.end());
    if (sorted.empty() || !(sorted.back() > sorted.front())) return identity;

    ToneCurve curve;
    if (contrast == LicContrast::Stretch) {
        curve.low = percentile(sorted, kStretchLowShare);
        curve.high = percentile(sorted, kStretchHighShare);
        // Over 99% of the pixels on one value: stretch what range there is rather than none.
        if (!(curve.high > curve.low)) curve.low = sorted.front(), curve.high = sorted.back();
        curve.values = {0.0f, 1.0f};
    } else {
        curve.low = sorted.front();
        curve.high = sorted.back();
        curve.values = cumulative_shares(sorted, curve.low, curve.high, kEqualizeBins);
    }
    return curve;
}

void check_sweepable(LicContrast contrast) {
    if (contrast != LicContrast::Off)
        throw Error(std::string("contrast=") + name_of(kLicContrastNames, contrast) +
                    " draws each image through a tone curve of its own, so a sweep's errors would measure the curves "
                    "too: sweep with contrast=off");
}

}  // namespace gsv
