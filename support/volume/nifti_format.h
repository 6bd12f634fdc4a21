#pragma once
// Internal to nifti_file.cpp (reading) and nifti_file_save.cpp (writing): the NIfTI-1 header's layout and
// datatype codes, as the standard's nifti1.h defines them (NIfTI Data Format Working Group, 2004,
// https://nifti.nimh.nih.gov/nifti-1), and bytes in either order.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

namespace gsv::nifti_format {

static_assert(std::numeric_limits<double>::is_iec559 && sizeof(double) == 8, "NIfTI float64 needs IEEE 754 doubles");
static_assert(std::numeric_limits<float>::is_iec559 && sizeof(float) == 4, "NIfTI float32 needs IEEE 754 floats");

// Byte offsets of the fields the kit reads or writes, in the 348-byte header.
inline constexpr std::size_t kHeaderBytes = 348;
inline constexpr std::size_t kSizeofHdr = 0;      // int32, 348 in the file's own byte order
inline constexpr std::size_t kDim = 40;           // int16[8]: dim[0] = rank, dim[1..7] = sizes
inline constexpr std::size_t kDatatype = 70;      // int16
inline constexpr std::size_t kBitpix = 72;        // int16
inline constexpr std::size_t kPixdim = 76;        // float32[8]: pixdim[1..3] = voxel spacing
inline constexpr std::size_t kVoxOffset = 108;    // float32: where the voxels start
inline constexpr std::size_t kSclSlope = 112;     // float32
inline constexpr std::size_t kSclInter = 116;     // float32
inline constexpr std::size_t kXyztUnits = 123;    // char: spatial units in bits 0..2
inline constexpr std::size_t kDescrip = 148;      // char[80]
inline constexpr std::size_t kDescripBytes = 80;
inline constexpr std::size_t kQformCode = 252;    // int16
inline constexpr std::size_t kQuatern = 256;      // float32[3] quatern_b, c, d, then qoffset_x, y, z
inline constexpr std::size_t kMagic = 344;        // char[4]
// A single-file .nii has 4 extension-flag bytes after the header, so its voxels start at 352 or later.
inline constexpr std::uint64_t kMinVoxOffset = 352;

inline constexpr int kSpatialUnitsMetre = 1, kSpatialUnitsMm = 2, kSpatialUnitsMicron = 3;
inline constexpr int kQformScannerAnat = 1;

struct Datatype {
    int code;
    const char* name;
    int bytes;
    bool is_signed, is_float;
};

// The datatypes the kit reads. Complex, RGB and 64-bit integer voxels have no single float32 value.
inline constexpr Datatype kDatatypes[] = {
    {2, "uint8", 1, false, false},   {256, "int8", 1, true, false},  {4, "int16", 2, true, false},
    {512, "uint16", 2, false, false}, {8, "int32", 4, true, false},  {16, "float32", 4, true, true},
    {64, "float64", 8, true, true},
};
inline constexpr int kFloat32 = 16;

inline const Datatype* find_datatype(int code) {
    for (const Datatype& type : kDatatypes)
        if (type.code == code) return &type;
    return nullptr;
}

// Names of the codes the kit does not read, so a refusal says what the file holds.
inline const char* unsupported_datatype_name(int code) {
    switch (code) {
        case 1: return "binary";
        case 32: return "complex64";
        case 128: return "rgb24";
        case 768: return "uint32";
        case 1024: return "int64";
        case 1280: return "uint64";
        case 1536: return "float128";
        case 1792: return "complex128";
        case 2048: return "complex256";
        case 2304: return "rgba32";
        default: return "unknown";
    }
}

// An unsigned integer of `bytes` bytes (1, 2, 4 or 8) stored in the given order.
inline std::uint64_t load_uint(const unsigned char* p, int bytes, bool big_endian) {
    std::uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) value |= std::uint64_t(p[big_endian ? bytes - 1 - i : i]) << (8 * i);
    return value;
}

inline void store_uint(std::uint64_t value, unsigned char* p, int bytes) {  // little-endian, as the kit writes
    for (int i = 0; i < bytes; ++i) p[i] = static_cast<unsigned char>(value >> (8 * i));
}

inline float float_from_bits(std::uint32_t bits) {
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

inline double double_from_bits(std::uint64_t bits) {
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

inline std::uint32_t bits_of(float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// One voxel of `type` as a double; exact for every type read here (32-bit integers fit a double's 53 bits).
inline double decode_voxel(const unsigned char* p, const Datatype& type, bool big_endian) {
    const std::uint64_t raw = load_uint(p, type.bytes, big_endian);
    if (type.is_float) return type.bytes == 4 ? double(float_from_bits(std::uint32_t(raw))) : double_from_bits(raw);
    if (!type.is_signed) return double(raw);
    // Two's complement: the top bit of a `bytes`-byte integer weighs -2^(8 bytes - 1).
    const int bits = 8 * type.bytes;
    const std::int64_t value = std::int64_t(raw) - ((raw >> (bits - 1)) & 1 ? (std::int64_t(1) << bits) : 0);
    return double(value);
}

inline std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

}  // namespace gsv::nifti_format
