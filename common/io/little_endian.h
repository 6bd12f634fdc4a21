#pragma once
// float32 and uint32 values in little-endian byte order, the order the kit's binary data files (.flow, .height,
// .f32, .f32s) store. Assembled from and split into bytes, so the host's own byte order never matters.
#include <cstdint>
#include <cstring>
#include <limits>

namespace gsv {

// The files hold IEEE binary32 bit patterns; a host with another float format cannot share them.
static_assert(std::numeric_limits<float>::is_iec559 && sizeof(float) == 4, "data files need IEEE 754 floats");

inline std::uint32_t u32_from_le_bytes(const unsigned char* bytes) {
    return std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 | std::uint32_t(bytes[2]) << 16 |
           std::uint32_t(bytes[3]) << 24;
}

inline void u32_to_le_bytes(std::uint32_t value, unsigned char* bytes) {
    for (int i = 0; i < 4; ++i) bytes[i] = static_cast<unsigned char>(value >> (8 * i));
}

inline float float_from_le_bytes(const unsigned char* bytes) {
    const std::uint32_t bits = u32_from_le_bytes(bytes);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

inline void float_to_le_bytes(float value, unsigned char* bytes) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    u32_to_le_bytes(bits, bytes);
}

}  // namespace gsv
