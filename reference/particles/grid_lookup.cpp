// GL's trilinear clamp-to-edge lookup of a velocity grid, on the CPU.
#include "reference/particles/grid_lookup.h"

#include <cmath>
#include <cstddef>

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

glm::dvec3 grid_lookup(const VelocityGrid& grid, glm::dvec3 p) { return trilinear(grid, p); }

glm::vec3 grid_lookup(const VelocityGrid& grid, glm::vec3 p) { return trilinear(grid, p); }

}  // namespace gsv
