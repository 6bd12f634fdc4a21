// A particle scene's field on a 3D texel grid, and GL's trilinear clamp-to-edge lookup of it.
#include "support/particles/particle_grid.h"

#include "common/core/error.h"

#include <cmath>
#include <cstddef>
#include <string>

namespace gsv {
namespace {

// Index i clamped to 0 .. n-1 (GL_CLAMP_TO_EDGE applied to each of the two texels on its own). Tested as a
// floating-point value before it becomes an int, so that a huge or NaN coordinate is never converted.
template <class T>
int clamp_index(T i, int n) {
    if (!(i >= T(0))) return 0;
    return i <= T(n - 1) ? static_cast<int>(i) : n - 1;
}

// Both ends of the mix are exact ((1 - 0) a + 0 b = a), which is what makes a texel centre return its texel.
template <class T>
glm::tvec3<T> mix_exact(const glm::tvec3<T>& a, const glm::tvec3<T>& b, T f) {
    return (T(1) - f) * a + f * b;
}

template <class T>
glm::tvec3<T> trilinear(const VelocityGrid& grid, const glm::tvec3<T>& p) {
    const int n = grid.n;
    const glm::tvec3<T> x = (p + T(1)) / T(2) * T(n) - T(0.5);
    const glm::tvec3<T> lower = glm::floor(x);
    const glm::tvec3<T> f = x - lower;
    int i[2], j[2], k[2];
    i[0] = clamp_index(lower.x, n), i[1] = clamp_index(lower.x + T(1), n);
    j[0] = clamp_index(lower.y, n), j[1] = clamp_index(lower.y + T(1), n);
    k[0] = clamp_index(lower.z, n), k[1] = clamp_index(lower.z + T(1), n);
    const auto at = [&](int a, int b, int c) {
        const float* t = grid.texels.data() + 3 * ((static_cast<std::size_t>(k[c]) * n + j[b]) * n + i[a]);
        return glm::tvec3<T>(T(t[0]), T(t[1]), T(t[2]));
    };
    // Along x, then y, then z.
    const auto plane = [&](int c) {
        return mix_exact(mix_exact(at(0, 0, c), at(1, 0, c), f.x), mix_exact(at(0, 1, c), at(1, 1, c), f.x), f.y);
    };
    return mix_exact(plane(0), plane(1), f.z);
}

}  // namespace

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

glm::dvec3 VelocityGrid::lookup(glm::dvec3 p) const { return trilinear(*this, p); }

glm::vec3 VelocityGrid::lookup(glm::vec3 p) const { return trilinear(*this, p); }

}  // namespace gsv
