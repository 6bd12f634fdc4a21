#include "reference/flow/time_slices.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace gsv {

double slice_coordinate(double time, double period, int slices, TimeWrap wrap) {
    if (slices < 1) throw Error("time slices: " + std::to_string(slices) + " slices; at least 1 is needed");
    if (!(period > 0) || !std::isfinite(period) || !std::isfinite(time))
        throw Error("time slices: time " + std::to_string(time) + " or period " + std::to_string(period) + " is not usable");
    const double s = time / period * slices;
    if (wrap == TimeWrap::Clamp) return std::clamp(s, 0.0, static_cast<double>(slices - 1));
    const double wrapped = std::fmod(s, static_cast<double>(slices));
    return wrapped < 0 ? wrapped + slices : wrapped;
}

SliceMix slice_mix(double time, double period, int slices, TimeWrap wrap, TimeBlend blend) {
    const double s = slice_coordinate(time, period, slices, wrap);
    const auto bounded = [&](int k) { return wrap == TimeWrap::Repeat ? k % slices : std::min(k, slices - 1); };
    SliceMix mix;
    if (blend == TimeBlend::Nearest) {
        mix.first = mix.second = bounded(static_cast<int>(std::floor(s + 0.5)));
        return mix;
    }
    const int k = static_cast<int>(std::floor(s));
    mix.first = bounded(k);
    mix.second = bounded(k + 1);
    mix.weight = s - k;
    return mix;
}

}  // namespace gsv
