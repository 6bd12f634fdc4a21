// Reading NIfTI-1 files, .nii and .nii.gz (support/volume/nifti_file.h): read_nifti_header and load_nifti.
#include "support/volume/nifti_file.h"

#include "common/core/error.h"
#include "support/volume/nifti_format.h"

#ifndef __EMSCRIPTEN__
#include <zlib.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace gsv {
namespace {

using namespace nifti_format;

// Voxels are read and converted this many bytes at a time (a multiple of 8), so memory grows only with
// bytes really in the file.
constexpr std::size_t kChunkBytes = std::size_t(1) << 20;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
    throw Error("NIfTI file " + quoted(path) + ": " + what);
}

std::string number(double value) {
    std::ostringstream out;
    out.precision(9);
    out << value;
    return out.str();
}

std::string voxel_name(std::uint64_t index, int nx, int ny) {
    const std::uint64_t x = std::uint64_t(nx), xy = x * std::uint64_t(ny);
    return "voxel (" + std::to_string(index % x) + ", " + std::to_string(index / x % std::uint64_t(ny)) + ", " +
           std::to_string(index / xy) + ")";
}

// The first bytes of the file (up to the header and extension flag), and its size, opened the way every
// check below needs: a .nii as it is, a .nii.gz decompressed (most public MRI data is gzipped).
struct Opened {
    std::unique_ptr<std::istream> in;
    std::uint64_t size = 0;  // of the NIfTI bytes: decompressed, for a .nii.gz
    bool gzipped = false;
    std::vector<unsigned char> head;
};

std::string inflate_file(const std::filesystem::path& path) {
#ifdef __EMSCRIPTEN__
    // Emscripten's frozen cache on Debian has no zlib (the browser edition, cmake/web.cmake).
    fail(path, "is gzip-compressed, which the browser edition cannot read: decompress it (gunzip) first");
#else
    // A volume the kit can draw is far below this; a gzip bomb is not.
    constexpr std::uint64_t kMaxInflatedBytes = std::uint64_t(2) << 30;
    gzFile gz = gzopen(path.string().c_str(), "rb");
    if (!gz) fail(path, "cannot open it to decompress");
    std::string out;
    std::vector<char> buffer(std::size_t(1) << 20);
    for (;;) {
        const int n = gzread(gz, buffer.data(), static_cast<unsigned>(buffer.size()));
        if (n > 0) out.append(buffer.data(), static_cast<std::size_t>(n));
        if (out.size() > kMaxInflatedBytes) {
            gzclose(gz);
            fail(path, "decompresses to more than " + std::to_string(kMaxInflatedBytes >> 30) + " GiB: not a volume this kit draws");
        }
        if (n > 0) continue;
        int code = Z_OK;
        // gzerror's text lives in the gzFile's state: copied before gzclose frees it (reading it after was
        // a use after free that put stray bytes, newlines too, into the message).
        const char* error_text = gzerror(gz, &code);
        const std::string message = error_text ? error_text : "";
        const bool ended = gzeof(gz) != 0;
        gzclose(gz);
        if (n < 0 || (code != Z_OK && code != Z_STREAM_END) || !ended)
            fail(path, "is gzip-compressed but its data is corrupt or cut short (zlib: " +
                           (message.empty() ? std::string("unexpected end of file") : message) + ")");
        return out;
    }
#endif
}

void open_file(const std::filesystem::path& path, Opened& file) {
    std::error_code error;
    // A directory opens as a stream on Linux and would then read as an empty file.
    if (std::filesystem::is_directory(path, error)) fail(path, "is a directory, not a file");
    auto plain = std::make_unique<std::ifstream>(path, std::ios::binary);
    if (!*plain)
        throw Error("cannot read NIfTI file " + quoted(path) + ": " +
                    (std::filesystem::exists(path, error) ? "cannot open file" : "no such file"));
    unsigned char magic[2] = {0, 0};
    plain->read(reinterpret_cast<char*>(magic), 2);
    file.gzipped = plain->gcount() == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
    if (file.gzipped) {
        std::string inflated = inflate_file(path);
        file.size = inflated.size();
        file.in = std::make_unique<std::istringstream>(std::move(inflated), std::ios::binary);
    } else {
        file.size = std::filesystem::file_size(path, error);
        if (error) fail(path, "cannot tell its size (" + error.message() + ")");
        plain->clear();
        plain->seekg(0);
        file.in = std::move(plain);
    }
    file.head.resize(static_cast<std::size_t>(std::min<std::uint64_t>(file.size, kMinVoxOffset)));
    file.in->read(reinterpret_cast<char*>(file.head.data()), static_cast<std::streamsize>(file.head.size()));
    if (static_cast<std::size_t>(file.in->gcount()) != file.head.size()) fail(path, "read error");
}

// Decides the byte order from sizeof_hdr, and refuses what is not a single-file NIfTI-1, saying what it
// looks like instead when that is clear.
bool check_identity(const std::filesystem::path& path, const Opened& file) {
    const std::vector<unsigned char>& h = file.head;
    if (h.size() >= 2 && h[0] == 0x1f && h[1] == 0x8b)
        fail(path, "is gzip-compressed twice: gunzip it once to a .nii.gz");
    if (h.size() < kHeaderBytes)
        fail(path, "is " + std::to_string(file.size) + " bytes" + (file.gzipped ? " decompressed" : "") +
                       ", too short for the 348-byte NIfTI-1 header");
    const std::uint64_t little = load_uint(h.data() + kSizeofHdr, 4, false), big = load_uint(h.data() + kSizeofHdr, 4, true);
    if (little == 540 || big == 540) fail(path, "is NIfTI-2 (sizeof_hdr 540), which this kit does not read");
    if (little != kHeaderBytes && big != kHeaderBytes) {
        // The .img of a pair is voxels only; its header is the .hdr beside it.
        const bool image_half = path.extension() == ".img";
        fail(path, "not a NIfTI-1 file: sizeof_hdr is " + std::to_string(std::int32_t(little)) + " (" +
                       std::to_string(std::int32_t(big)) + " read big-endian), not 348" +
                       (image_half ? " (the voxels of a .hdr/.img pair? pairs are not supported: use a single .nii)" : ""));
    }
    const bool big_endian = big == kHeaderBytes;
    const unsigned char* magic = h.data() + kMagic;
    if (std::memcmp(magic, "ni1\0", 4) == 0)
        fail(path, "is the header of a .hdr/.img pair (magic 'ni1'), which this kit does not read: only single-file "
                   ".nii (magic 'n+1')");
    if (std::memcmp(magic, "n+1\0", 4) != 0) {
        std::string shown;  // up to its first NUL, with bytes that would garble a terminal shown as '?'
        for (int i = 0; i < 4 && magic[i] != 0; ++i) shown += magic[i] >= 0x20 && magic[i] <= 0x7e ? char(magic[i]) : '?';
        fail(path, "magic is '" + shown + "', not 'n+1' of a single-file NIfTI-1 (an ANALYZE 7.5 .hdr, or a "
                   ".hdr/.img pair?)");
    }
    return big_endian;
}

void read_dims(const std::filesystem::path& path, const unsigned char* h, bool big, NiftiHeader& header) {
    int dim[8];
    for (int i = 0; i < 8; ++i) dim[i] = std::int16_t(load_uint(h + kDim + 2 * i, 2, big));
    if (dim[0] == 4 && dim[4] != 1)
        fail(path, "dim[4] is " + std::to_string(dim[4]) + ": a series of volumes, and this kit reads one (dim[4] = 1)");
    if (dim[0] != 3 && dim[0] != 4)
        fail(path, "dim[0] is " + std::to_string(dim[0]) + ": this kit reads 3D volumes (dim[0] = 3, or 4 with dim[4] = 1)");
    for (int axis = 1; axis <= 3; ++axis)
        if (dim[axis] < 1 || dim[axis] > kMaxVolumeSide)
            fail(path, "dim[" + std::to_string(axis) + "] is " + std::to_string(dim[axis]) + ", not in 1.." +
                           std::to_string(kMaxVolumeSide));
    header.nx = dim[1], header.ny = dim[2], header.nz = dim[3];
    const std::uint64_t count = std::uint64_t(dim[1]) * std::uint64_t(dim[2]) * std::uint64_t(dim[3]);
    if (count > kMaxVolumeVoxels)
        fail(path, std::to_string(dim[1]) + "x" + std::to_string(dim[2]) + "x" + std::to_string(dim[3]) + " is " +
                       std::to_string(count) + " voxels, more than the " + std::to_string(kMaxVolumeVoxels) +
                       " this kit loads");
}

const Datatype& read_datatype(const std::filesystem::path& path, const unsigned char* h, bool big, NiftiHeader& header) {
    header.datatype = std::int16_t(load_uint(h + kDatatype, 2, big));
    header.bits_per_voxel = std::int16_t(load_uint(h + kBitpix, 2, big));
    const Datatype* type = find_datatype(header.datatype);
    if (!type)
        fail(path, "datatype " + std::to_string(header.datatype) + " (" + unsupported_datatype_name(header.datatype) +
                       ") is not supported (this kit reads uint8, int8, int16, uint16, int32, float32, float64)");
    // A bitpix that disagrees with the datatype means a damaged or hand-made header: which one is right?
    if (header.bits_per_voxel != 8 * type->bytes)
        fail(path, "bitpix " + std::to_string(header.bits_per_voxel) + " does not match datatype " +
                       std::to_string(type->code) + " (" + type->name + ", " + std::to_string(8 * type->bytes) + " bits)");
    return *type;
}

void read_spacing(const std::filesystem::path& path, const unsigned char* h, bool big, NiftiHeader& header) {
    // Spatial units are in bits 0..2 of xyzt_units; the time units above them do not concern a volume.
    const int units = h[kXyztUnits] & 7;
    const double to_mm = units == kSpatialUnitsMetre ? 1000.0 : units == kSpatialUnitsMicron ? 0.001 : 1.0;
    static const char* const kAxis[] = {"", "x", "y", "z"};
    for (int axis = 1; axis <= 3; ++axis) {
        const double value = float_from_bits(std::uint32_t(load_uint(h + kPixdim + 4 * axis, 4, big)));
        if (!std::isfinite(value) || value <= 0)
            fail(path, "pixdim[" + std::to_string(axis) + "] (the spacing along " + kAxis[axis] + ") is " + number(value) +
                           ", not a positive finite number");
        header.spacing[axis - 1] = value * to_mm;
    }
}

void read_offset_and_scaling(const std::filesystem::path& path, const unsigned char* h, bool big, NiftiHeader& header) {
    const double offset = float_from_bits(std::uint32_t(load_uint(h + kVoxOffset, 4, big)));
    // Above 2^53 a double is no longer every integer; no real file's voxels start anywhere near there.
    if (!(offset >= double(kMinVoxOffset)) || offset != std::floor(offset) || offset > 9007199254740992.0)
        fail(path, "vox_offset " + number(offset) + " is not a whole number of bytes from 352 (the header and its "
                   "extension flag) on");
    header.vox_offset = std::uint64_t(offset);
    header.scl_slope = float_from_bits(std::uint32_t(load_uint(h + kSclSlope, 4, big)));
    header.scl_inter = float_from_bits(std::uint32_t(load_uint(h + kSclInter, 4, big)));
    header.scaled = std::isfinite(header.scl_slope) && header.scl_slope != 0;
    if (header.scaled && !std::isfinite(header.scl_inter))
        fail(path, "scl_inter is " + number(header.scl_inter) + " with scl_slope " + number(header.scl_slope) +
                       ": the scaled values would not be finite");
}

NiftiHeader read_header(const std::filesystem::path& path, Opened& file) {
    open_file(path, file);
    NiftiHeader header;
    header.big_endian = check_identity(path, file);
    const unsigned char* h = file.head.data();
    const bool big = header.big_endian;
    read_dims(path, h, big, header);
    const Datatype& type = read_datatype(path, h, big, header);
    read_spacing(path, h, big, header);
    read_offset_and_scaling(path, h, big, header);
    const char* descrip = reinterpret_cast<const char*>(h + kDescrip);
    header.description.assign(descrip, std::find(descrip, descrip + kDescripBytes, '\0'));

    // The file's size is the honest bound: only a header it confirms may size an allocation.
    const std::uint64_t expected =
        std::uint64_t(header.nx) * std::uint64_t(header.ny) * std::uint64_t(header.nz) * std::uint64_t(type.bytes);
    const std::uint64_t found = file.size > header.vox_offset ? file.size - header.vox_offset : 0;
    if (found != expected)
        fail(path, "expected " + std::to_string(expected) + " bytes of voxels after offset " +
                       std::to_string(header.vox_offset) + ", found " + std::to_string(found) +
                       (file.gzipped ? " decompressed" : "") + " (" +
                       std::to_string(header.nx) + "x" + std::to_string(header.ny) + "x" + std::to_string(header.nz) +
                       " " + type.name + ")");
    return header;
}

}  // namespace

const char* nifti_datatype_name(int code) {
    const Datatype* type = find_datatype(code);
    return type ? type->name : unsupported_datatype_name(code);
}

NiftiHeader read_nifti_header(const std::filesystem::path& path) {
    Opened file;
    return read_header(path, file);
}

Volume load_nifti(const std::filesystem::path& path) {
    Opened file;
    const NiftiHeader header = read_header(path, file);
    const Datatype& type = *find_datatype(header.datatype);

    Volume volume;
    volume.nx = header.nx, volume.ny = header.ny, volume.nz = header.nz;
    volume.spacing = header.spacing;
    volume.name = path.stem().string();
    const std::size_t count = std::size_t(header.nx) * std::size_t(header.ny) * std::size_t(header.nz);
    volume.values.resize(count);

    const bool identity = !header.scaled || (header.scl_slope == 1 && header.scl_inter == 0);
    file.in->seekg(static_cast<std::streamoff>(header.vox_offset));
    std::vector<unsigned char> chunk(std::min<std::size_t>(kChunkBytes, count * std::size_t(type.bytes)));
    const std::size_t per_chunk = chunk.size() / std::size_t(type.bytes);
    for (std::size_t done = 0; done < count;) {
        const std::size_t n = std::min(count - done, per_chunk);
        file.in->read(reinterpret_cast<char*>(chunk.data()), static_cast<std::streamsize>(n * std::size_t(type.bytes)));
        if (static_cast<std::size_t>(file.in->gcount()) != n * std::size_t(type.bytes))
            fail(path, "read error after " + std::to_string(done) + " voxels (did the file change while it was read?)");
        for (std::size_t i = 0; i < n; ++i) {
            const double stored = decode_voxel(chunk.data() + i * std::size_t(type.bytes), type, header.big_endian);
            if (!std::isfinite(stored))
                fail(path, voxel_name(done + i, header.nx, header.ny) + " is " + (std::isnan(stored) ? "NaN" : "infinite"));
            // Slope 1 and intercept 0 (what most writers store) leave the value alone: -0 + 0 would be +0.
            const double value = identity ? stored : header.scl_slope * stored + header.scl_inter;
            // Checked before the conversion, which is undefined for a double beyond float's range.
            if (!(std::abs(value) <= double(std::numeric_limits<float>::max())))
                fail(path, voxel_name(done + i, header.nx, header.ny) + " is " + number(value) +
                               (header.scaled ? " after scaling" : "") + ", beyond float32");
            volume.values[done + i] = static_cast<float>(value);
        }
        done += n;
    }
    volume.update_range();
    return volume;
}

}  // namespace gsv
