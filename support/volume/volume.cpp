// Volume's accessors, its normalisation, and GL's trilinear clamp-to-edge lookup of it.
#include "support/volume/volume.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace gsv {
namespace {

// How far from a texel centre, in texels, a lookup still counts as exactly the centre (see Volume::sample).
constexpr double kCentreSnapTexels = 1.0 / (1 << 30);

std::string volume_label(const Volume& volume) { return "volume '" + volume.name + "'"; }

void check_shape(const Volume& volume, const char* who) {
    const std::size_t count = static_cast<std::size_t>(std::max(volume.nx, 0)) *
                              static_cast<std::size_t>(std::max(volume.ny, 0)) *
                              static_cast<std::size_t>(std::max(volume.nz, 0));
    if (volume.nx < 1 || volume.ny < 1 || volume.nz < 1 || volume.values.size() != count)
        throw Error(std::string(who) + ": " + volume_label(volume) + " is " + std::to_string(volume.nx) + "x" +
                    std::to_string(volume.ny) + "x" + std::to_string(volume.nz) + " but holds " +
                    std::to_string(volume.values.size()) + " values");
}

// One axis of the lookup: the two voxels to mix and the weight of the second. Clamping x to [0, n - 1]
// before the floor is CLAMP_TO_EDGE applied to both voxels (beyond the last centre both are the edge
// voxel), and it keeps an infinite coordinate from becoming inf - inf = NaN.
struct AxisWeights {
    int i0, i1;
    double f;
};

AxisWeights axis_weights(double s, int n) {
    double x = std::fma(s, static_cast<double>(n), -0.5);
    x = std::clamp(x, 0.0, static_cast<double>(n - 1));
    const double centre = std::round(x);
    if (std::abs(x - centre) <= kCentreSnapTexels) x = centre;
    // The upper end x = n - 1 is voxel n - 2 with weight 1, so i0 + 1 stays inside the grid.
    const int i0 = std::min(static_cast<int>(x), std::max(n - 2, 0));
    return {i0, std::min(i0 + 1, n - 1), x - i0};
}

// Exact at both ends ((1 - 0) a + 0 b = a) and for equal values, which (1 - f) a + f a is not in general:
// a constant volume must sample to its constant, or its differences would not be exactly zero.
double mix_exact(double a, double b, double f) { return a == b ? a : (1.0 - f) * a + f * b; }

}  // namespace

std::size_t Volume::index(int i, int j, int k) const {
    check_shape(*this, "Volume::index");
    if (i < 0 || j < 0 || k < 0 || i >= nx || j >= ny || k >= nz)
        throw Error("Volume::index: voxel (" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) +
                    ") is outside the " + std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz) +
                    " grid of " + volume_label(*this));
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(ny) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(nx) +
           static_cast<std::size_t>(i);
}

float Volume::at(int i, int j, int k) const { return values[index(i, j, k)]; }

glm::dvec3 Volume::extent() const { return glm::dvec3(nx, ny, nz) * spacing; }

void Volume::update_range() {
    if (values.empty()) {
        min = max = 0;
        return;
    }
    const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
    min = *lowest;
    max = *highest;
}

void Volume::set_percentile_window(double low_share, double high_share) {
    if (!(0.0 <= low_share && low_share < high_share && high_share <= 1.0))
        throw Error("Volume::set_percentile_window: shares " + std::to_string(low_share) + " and " +
                    std::to_string(high_share) + " must satisfy 0 <= low < high <= 1");
    if (values.empty()) throw Error("Volume::set_percentile_window: " + volume_label(*this) + " has no values");
    std::vector<float> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    const auto rank = [&](double share) {
        return sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(share * static_cast<double>(sorted.size())))];
    };
    min = rank(low_share);
    max = rank(high_share);
}

Volume Volume::with_y_and_z_exchanged() const {
    check_shape(*this, "Volume::with_y_and_z_exchanged");
    Volume result = *this;
    std::swap(result.ny, result.nz);
    std::swap(result.spacing.y, result.spacing.z);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) result.values[result.index(i, k, j)] = values[index(i, j, k)];
    return result;
}

Volume Volume::normalized() const {
    if (!std::isfinite(min) || !std::isfinite(max) || max < min)
        throw Error("Volume::normalized: " + volume_label(*this) + " has range [" + std::to_string(min) + ", " +
                    std::to_string(max) + "], not finite min <= max");
    Volume result = *this;
    const double low = min, width = double(max) - double(min);
    for (float& v : result.values)
        v = width > 0 ? static_cast<float>(std::clamp((double(v) - low) / width, 0.0, 1.0)) : 0.0f;
    result.min = 0;
    result.max = width > 0 ? 1.0f : 0.0f;
    return result;
}

double Volume::sample(glm::dvec3 texcoord) const {
    check_shape(*this, "Volume::sample");
    if (std::isnan(texcoord.x) || std::isnan(texcoord.y) || std::isnan(texcoord.z))
        return std::numeric_limits<double>::quiet_NaN();
    const AxisWeights x = axis_weights(texcoord.x, nx), y = axis_weights(texcoord.y, ny),
                      z = axis_weights(texcoord.z, nz);
    const auto v = [&](int i, int j, int k) { return double(values[(std::size_t(k) * ny + j) * nx + i]); };
    // Along x, then y, then z.
    const auto plane = [&](int k) {
        return mix_exact(mix_exact(v(x.i0, y.i0, k), v(x.i1, y.i0, k), x.f),
                         mix_exact(v(x.i0, y.i1, k), v(x.i1, y.i1, k), x.f), y.f);
    };
    return mix_exact(plane(z.i0), plane(z.i1), z.f);
}

}  // namespace gsv
