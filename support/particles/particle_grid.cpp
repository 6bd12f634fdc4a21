// A particle scene's field on a 3D texel grid.
#include "support/particles/particle_grid.h"

#include "common/core/error.h"

#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {

VelocityGrid VelocityGrid::sample(ParticleScene scene, int n) {
    if (n < kMinSide || n > kMaxSide)
        throw Error("velocity grid: side " + std::to_string(n) + " is not in " + std::to_string(kMinSide) + ".." +
                    std::to_string(kMaxSide));
    if (scene == ParticleScene::Gravity)
        throw Error(std::string("velocity grid: the ") + particle_scene_name(scene) + " scene has no velocity field");
    VelocityGrid grid;
    grid.n = n;
    grid.texels.resize(3 * static_cast<std::size_t>(n) * n * n);
    const auto centre = [n](int i) { return -1.0 + (2.0 * i + 1.0) / n; };
    std::size_t at = 0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec3 u = field_velocity<double>(scene, glm::dvec3(centre(i), centre(j), centre(k)));
                grid.texels[at++] = static_cast<float>(u.x);
                grid.texels[at++] = static_cast<float>(u.y);
                grid.texels[at++] = static_cast<float>(u.z);
            }
    return grid;
}

glm::vec3 VelocityGrid::texel(int i, int j, int k) const {
    if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n)
        throw Error("velocity grid: texel (" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) +
                    ") is outside the " + std::to_string(n) + "^3 grid");
    const float* t = texels.data() + 3 * ((static_cast<std::size_t>(k) * n + j) * n + i);
    return {t[0], t[1], t[2]};
}

}  // namespace gsv
