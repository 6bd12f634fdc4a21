#pragma once
// SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014;
// constants from Vigna's reference code, https://prng.di.unimi.it/splitmix64.c). The kit's random
// textures and seeded fields come from here rather than from <random>, whose distributions are allowed
// to differ between standard libraries: a seed must give the same image on every student's machine
// and on the grader's.
#include <cstdint>

namespace gsv {

inline constexpr std::uint64_t kSplitMix64Gamma = 0x9E3779B97F4A7C15ull;

// The output function alone: a bijection of 64-bit words whose every output bit depends on every
// input bit.
constexpr std::uint64_t splitmix64_mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// One step of the reference generator: with state 0 the first outputs are 0xE220A8397B1DCDAF,
// 0x6E789E6AA1B965F4, 0x06C45D188009454F.
constexpr std::uint64_t splitmix64_next(std::uint64_t& state) {
    state += kSplitMix64Gamma;
    return splitmix64_mix(state);
}

// The index-th draw of the stream keyed by `seed`, computed directly so that draws do not depend on
// the order (or the thread) that asks for them. The seed is mixed first so that seeds differing by a
// multiple of the gamma do not give shifted copies of one stream.
constexpr std::uint64_t hash64(std::uint64_t seed, std::uint64_t index) {
    std::uint64_t state = splitmix64_mix(seed) + index * kSplitMix64Gamma;
    return splitmix64_next(state);
}

// The top 24 bits as a float in [0, 1): every such value is exact in a float, so rounding can never
// produce 1.0f.
constexpr float unit_float(std::uint64_t bits) {
    return static_cast<float>(bits >> 40) * (1.0f / 16777216.0f);
}

// The top 53 bits as a double in [0, 1), exact for the same reason.
constexpr double unit_double(std::uint64_t bits) {
    return static_cast<double>(bits >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace gsv
