#pragma once
// The white-noise texture that line integral convolution smears along streamlines (Cabral and Leedom,
// "Imaging vector fields using line integral convolution", SIGGRAPH 1993): independent values per
// texel, so any visible structure in the LIC image comes from the flow and not from the noise.
#include <cstdint>
#include <vector>

namespace gsv {

// width*height values uniform in [0, 1), row-major with row 0 the bottom row (the order glTexImage2D
// expects). Texel (x, y) is gsv::hash64(seed, y*width + x), so the same seed gives bit-identical
// textures on every platform and compiler. Throws gsv::Error unless 1 <= width, height <= 8192.
std::vector<float> white_noise(int width, int height, std::uint64_t seed);

}  // namespace gsv
