// The 3x3x3 Sobel gradient of a Volume, voxel by voxel and for the whole volume.
#include "support/volume/sobel_gradient.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {
namespace {

void check_volume(const Volume& volume) {
    const glm::dvec3 s = volume.spacing;
    const auto ok = [](double v) { return std::isfinite(v) && v > 0; };
    if (!ok(s.x) || !ok(s.y) || !ok(s.z))
        throw Error("sobel_gradient: volume '" + volume.name + "' has spacing (" + std::to_string(s.x) + ", " +
                    std::to_string(s.y) + ", " + std::to_string(s.z) + "), not positive and finite");
    if (volume.nx < 1 || volume.ny < 1 || volume.nz < 1 ||
        volume.values.size() != static_cast<std::size_t>(volume.nx) * volume.ny * volume.nz)
        throw Error("sobel_gradient: volume '" + volume.name + "' holds " + std::to_string(volume.values.size()) +
                    " values for " + std::to_string(volume.nx) + "x" + std::to_string(volume.ny) + "x" +
                    std::to_string(volume.nz) + " voxels");
}

constexpr double kSmooth[3] = {1.0, 2.0, 1.0};  // across the axis; they sum to 4 each way, 16 over a plane

// One 1D pass over a whole grid of doubles along `axis`: the 1-2-1 average (derivative false) or the central
// difference over the spacing (true), neighbours clamped to the grid.
std::vector<double> pass(const std::vector<double>& in, const Volume& v, int axis, bool derivative) {
    const int n[3] = {v.nx, v.ny, v.nz};
    const std::size_t stride[3] = {1, static_cast<std::size_t>(v.nx), static_cast<std::size_t>(v.nx) * v.ny};
    const double spacing = axis == 0 ? v.spacing.x : axis == 1 ? v.spacing.y : v.spacing.z;
    std::vector<double> out(in.size());
    std::size_t at = 0;
    for (int k = 0; k < v.nz; ++k)
        for (int j = 0; j < v.ny; ++j)
            for (int i = 0; i < v.nx; ++i, ++at) {
                const int here = axis == 0 ? i : axis == 1 ? j : k;
                const std::size_t back = at - static_cast<std::size_t>(here - std::max(here - 1, 0)) * stride[axis];
                const std::size_t ahead = at + static_cast<std::size_t>(std::min(here + 1, n[axis] - 1) - here) * stride[axis];
                out[at] = derivative ? (in[ahead] - in[back]) / (2.0 * spacing) : (in[back] + 2.0 * in[at] + in[ahead]) / 4.0;
            }
    return out;
}

}  // namespace

glm::dvec3 sobel_gradient(const Volume& volume, int i, int j, int k) {
    check_volume(volume);
    volume.index(i, j, k);  // throws for a voxel outside the grid, which clamping would otherwise hide
    const auto at = [&](int a, int b, int c) {
        return static_cast<double>(volume.at(std::clamp(a, 0, volume.nx - 1), std::clamp(b, 0, volume.ny - 1),
                                             std::clamp(c, 0, volume.nz - 1)));
    };
    glm::dvec3 sum(0.0);
    for (int b = -1; b <= 1; ++b)
        for (int a = -1; a <= 1; ++a) {
            const double w = kSmooth[a + 1] * kSmooth[b + 1];
            sum.x += w * (at(i + 1, j + a, k + b) - at(i - 1, j + a, k + b));
            sum.y += w * (at(i + a, j + 1, k + b) - at(i + a, j - 1, k + b));
            sum.z += w * (at(i + a, j + b, k + 1) - at(i + a, j + b, k - 1));
        }
    return sum / (32.0 * volume.spacing);  // 16 for the weights, 2 spacings between the planes
}

std::vector<float> sobel_gradient_volume(const Volume& volume) {
    check_volume(volume);
    const std::vector<double> values(volume.values.begin(), volume.values.end());
    std::vector<float> out(3 * values.size());
    const auto store = [&](const std::vector<double>& component, int c) {
        for (std::size_t v = 0; v < component.size(); ++v) out[3 * v + static_cast<std::size_t>(c)] = static_cast<float>(component[v]);
    };
    // Component a: smoothed across the other two axes, then differenced along a.
    constexpr int kX = 0, kY = 1, kZ = 2;
    store(pass(pass(pass(values, volume, kZ, false), volume, kY, false), volume, kX, true), kX);
    const std::vector<double> smooth_x = pass(values, volume, kX, false);
    store(pass(pass(smooth_x, volume, kZ, false), volume, kY, true), kY);
    store(pass(pass(smooth_x, volume, kY, false), volume, kZ, true), kZ);
    return out;
}

}  // namespace gsv
