#include "support/flow/noise.h"

#include "common/core/error.h"
#include "common/core/splitmix64.h"

#include <cstddef>
#include <string>

namespace gsv {
namespace {

// Large enough for any photograph a lab uses, small enough that a mistyped size fails with a message
// instead of an allocation of many gigabytes.
constexpr int kMaxSide = 8192;

void check_side(const char* name, int value) {
    if (value < 1 || value > kMaxSide)
        throw Error(std::string("white_noise: ") + name + " must be 1.." + std::to_string(kMaxSide) + ", got " +
                    std::to_string(value));
}

}  // namespace

std::vector<float> white_noise(int width, int height, std::uint64_t seed) {
    check_side("width", width);
    check_side("height", height);
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    std::vector<float> texels(count);
    for (std::size_t i = 0; i < count; ++i) texels[i] = unit_float(hash64(seed, i));
    return texels;
}

}  // namespace gsv
