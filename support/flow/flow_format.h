#pragma once
// Internal to flow_file.cpp (reading) and flow_file_save.cpp (writing): the byte-level pieces of the .flow
// format (described in flow_field.h) that both sides must agree on.
#include "common/io/little_endian.h"
#include "support/flow/flow_field.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

namespace gsv::flow_format {

inline constexpr const char* kMagic = "GSVFLOW";
inline constexpr const char* kVersion = "1";
inline constexpr std::size_t kBytesPerTexel = 2 * sizeof(float);
// Files are read and written this many bytes at a time (a multiple of kBytesPerTexel), so neither side
// ever holds a second copy of a whole frame as bytes.
inline constexpr std::size_t kChunkBytes = std::size_t(1) << 20;

inline std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

// Counted in 64 bits: 4096 frames of 8192x8192 texels is 2^41 bytes, past a 32-bit size_t.
inline std::uint64_t velocity_bytes(int frames, int width, int height) {
    return std::uint64_t(frames) * std::uint64_t(width) * std::uint64_t(height) * kBytesPerTexel;
}

// " of frame k" in a sequence; "" in a single field, where naming the frame would only add noise.
inline std::string of_frame(int frame, int frames) {
    return frames == 1 ? std::string() : " of frame " + std::to_string(frame);
}

// "vx at texel (x, y) of frame k" for velocity value `index` of a frame; y counts from the bottom row as
// everywhere in the kit.
inline std::string value_name(std::size_t index, int width, const std::string& of_frame = "") {
    const std::size_t texel = index / 2;
    return std::string(index % 2 ? "vy" : "vx") + " at texel (" + std::to_string(texel % width) + ", " +
           std::to_string(texel / width) + ")" + of_frame;
}

inline const char* non_finite_kind(float value) { return std::isnan(value) ? "NaN" : "infinite"; }

// Why `frames` frames of width x height texels cannot be a .flow file, or "" when they can be.
inline std::string over_size_limit(int frames, int width, int height) {
    const std::uint64_t bytes = velocity_bytes(frames, width, height);
    if (bytes <= kMaxFlowBytes) return "";
    return std::to_string(frames) + " frames of " + std::to_string(width) + "x" + std::to_string(height) +
           " texels need " + std::to_string(bytes) + " bytes of velocities, more than the " +
           std::to_string(kMaxFlowBytes) + " (1 GiB) a .flow file may hold";
}

}  // namespace gsv::flow_format
