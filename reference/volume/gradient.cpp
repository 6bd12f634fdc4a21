// Finite-difference gradients of a Volume in physical units, and their safe normalisation.
#include "reference/volume/gradient.h"

#include "common/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace gsv {
namespace {

void check_spacing(const Volume& volume, const char* who) {
    const glm::dvec3 s = volume.spacing;
    const auto ok = [](double v) { return std::isfinite(v) && v > 0; };
    if (!ok(s.x) || !ok(s.y) || !ok(s.z))
        throw Error(std::string(who) + ": volume '" + volume.name + "' has spacing (" + std::to_string(s.x) + ", " +
                    std::to_string(s.y) + ", " + std::to_string(s.z) + "), not positive and finite");
}

// Value of voxel (i, j, k) with each index clamped to the grid, as CLAMP_TO_EDGE reads a neighbour.
double clamped(const Volume& volume, int i, int j, int k) {
    return volume.at(std::clamp(i, 0, volume.nx - 1), std::clamp(j, 0, volume.ny - 1), std::clamp(k, 0, volume.nz - 1));
}

void check_step(double step_voxels, const char* who) {
    if (!std::isfinite(step_voxels) || step_voxels <= 0)
        throw Error(std::string(who) + ": step " + std::to_string(step_voxels) + " voxels is not positive and finite");
}

}  // namespace

glm::dvec3 central_difference(const Volume& volume, int i, int j, int k) {
    check_spacing(volume, "central_difference");
    volume.index(i, j, k);  // throws for a voxel outside the grid, which clamping would otherwise hide
    const glm::dvec3 d(clamped(volume, i + 1, j, k) - clamped(volume, i - 1, j, k),
                       clamped(volume, i, j + 1, k) - clamped(volume, i, j - 1, k),
                       clamped(volume, i, j, k + 1) - clamped(volume, i, j, k - 1));
    return d / (2.0 * volume.spacing);
}

glm::dvec3 forward_difference(const Volume& volume, int i, int j, int k) {
    check_spacing(volume, "forward_difference");
    const double here = volume.at(i, j, k);
    const glm::dvec3 d(clamped(volume, i + 1, j, k) - here, clamped(volume, i, j + 1, k) - here,
                       clamped(volume, i, j, k + 1) - here);
    return d / volume.spacing;
}

glm::dvec3 central_difference(const Volume& volume, glm::dvec3 texcoord, double step_voxels) {
    check_spacing(volume, "central_difference");
    check_step(step_voxels, "central_difference");
    const glm::dvec3 offset = step_voxels / glm::dvec3(volume.nx, volume.ny, volume.nz);
    const glm::dvec3 dx(offset.x, 0, 0), dy(0, offset.y, 0), dz(0, 0, offset.z);
    const glm::dvec3 d(volume.sample(texcoord + dx) - volume.sample(texcoord - dx),
                       volume.sample(texcoord + dy) - volume.sample(texcoord - dy),
                       volume.sample(texcoord + dz) - volume.sample(texcoord - dz));
    return d / (2.0 * step_voxels * volume.spacing);
}

glm::dvec3 forward_difference(const Volume& volume, glm::dvec3 texcoord, double step_voxels) {
    check_spacing(volume, "forward_difference");
    check_step(step_voxels, "forward_difference");
    const glm::dvec3 offset = step_voxels / glm::dvec3(volume.nx, volume.ny, volume.nz);
    const double here = volume.sample(texcoord);
    const glm::dvec3 d(volume.sample(texcoord + glm::dvec3(offset.x, 0, 0)) - here,
                       volume.sample(texcoord + glm::dvec3(0, offset.y, 0)) - here,
                       volume.sample(texcoord + glm::dvec3(0, 0, offset.z)) - here);
    return d / (step_voxels * volume.spacing);
}

glm::dvec3 safe_normalize(glm::dvec3 g) {
    if (!std::isfinite(g.x) || !std::isfinite(g.y) || !std::isfinite(g.z))
        return glm::dvec3(std::numeric_limits<double>::quiet_NaN());
    const double largest = std::max({std::abs(g.x), std::abs(g.y), std::abs(g.z)});
    if (largest == 0) return glm::dvec3(0.0);
    const glm::dvec3 scaled = g / largest;  // largest component +-1: its squared length is in [1, 3]
    return scaled / std::sqrt(glm::dot(scaled, scaled));
}

}  // namespace gsv
