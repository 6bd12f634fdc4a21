// Writing little-endian float32 NIfTI-1 files (support/volume/nifti_file.h): save_nifti.
#include "support/volume/nifti_file.h"

#include "common/core/error.h"
#include "support/volume/nifti_format.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace gsv {
namespace {

using namespace nifti_format;

constexpr std::size_t kChunkBytes = std::size_t(1) << 20;

void put_i16(unsigned char* h, std::size_t at, int value) { store_uint(std::uint16_t(std::int16_t(value)), h + at, 2); }
void put_f32(unsigned char* h, std::size_t at, float value) { store_uint(bits_of(value), h + at, 4); }

// Everything load_nifti would refuse, checked before the file is opened, so a refused save leaves no
// half-written file behind.
void check_savable(const std::filesystem::path& path, const Volume& volume) {
    const auto refuse = [&](const std::string& what) { throw Error("save_nifti " + quoted(path) + ": " + what); };
    const auto side_ok = [](int side) { return side >= 1 && side <= kMaxVolumeSide; };
    if (!side_ok(volume.nx) || !side_ok(volume.ny) || !side_ok(volume.nz))
        refuse("size " + std::to_string(volume.nx) + "x" + std::to_string(volume.ny) + "x" + std::to_string(volume.nz) +
               " is not in 1.." + std::to_string(kMaxVolumeSide) + " each way");
    const std::size_t count = std::size_t(volume.nx) * std::size_t(volume.ny) * std::size_t(volume.nz);
    if (count > kMaxVolumeVoxels) refuse(std::to_string(count) + " voxels are more than " + std::to_string(kMaxVolumeVoxels));
    if (volume.values.size() != count)
        refuse(std::to_string(volume.values.size()) + " values for " + std::to_string(count) + " voxels");
    for (int axis = 0; axis < 3; ++axis) {
        // The spacing is stored as float32: what the loader will see is the rounded value.
        const double spacing = volume.spacing[axis];
        const bool fits = std::isfinite(spacing) && spacing > 0 && spacing <= double(std::numeric_limits<float>::max());
        if (!fits || !(static_cast<float>(spacing) > 0))
            refuse("spacing along " + std::string(1, "xyz"[axis]) + " " + std::to_string(spacing) +
                   " is not a positive finite float32");
    }
    const auto bad = std::find_if(volume.values.begin(), volume.values.end(), [](float v) { return !std::isfinite(v); });
    if (bad != volume.values.end()) {
        const std::size_t index = std::size_t(bad - volume.values.begin());
        const std::size_t nx = std::size_t(volume.nx), ny = std::size_t(volume.ny);
        refuse("voxel (" + std::to_string(index % nx) + ", " + std::to_string(index / nx % ny) + ", " +
               std::to_string(index / (nx * ny)) + ") is " + (std::isnan(*bad) ? "NaN" : "infinite"));
    }
}

std::vector<unsigned char> header_bytes(const Volume& volume) {
    std::vector<unsigned char> h(kMinVoxOffset, 0);  // the header, then 4 zero bytes: no extensions
    store_uint(kHeaderBytes, h.data() + kSizeofHdr, 4);
    const int dim[8] = {3, volume.nx, volume.ny, volume.nz, 1, 1, 1, 1};
    for (int i = 0; i < 8; ++i) put_i16(h.data(), kDim + 2 * i, dim[i]);
    put_i16(h.data(), kDatatype, kFloat32);
    put_i16(h.data(), kBitpix, 32);
    // pixdim[0] is qfac, the handedness the qform uses: +1, a right-handed voxel frame.
    put_f32(h.data(), kPixdim, 1.0f);
    for (int axis = 0; axis < 3; ++axis) put_f32(h.data(), kPixdim + 4 * (axis + 1), static_cast<float>(volume.spacing[axis]));
    put_f32(h.data(), kVoxOffset, float(kMinVoxOffset));
    put_f32(h.data(), kSclSlope, 1.0f);
    put_f32(h.data(), kSclInter, 0.0f);
    h[kXyztUnits] = kSpatialUnitsMm;
    const std::string description = ("gsv " + volume.name).substr(0, kDescripBytes - 1);
    std::copy(description.begin(), description.end(), h.begin() + kDescrip);
    // qform_code 1 with quatern_b = c = d = 0 (the identity rotation) and a zero offset: other tools place
    // voxel (i, j, k) at (i sx, j sy, k sz) mm, as the kit does up to its half-voxel.
    put_i16(h.data(), kQformCode, kQformScannerAnat);
    std::copy_n("n+1", 4, h.begin() + kMagic);
    return h;
}

}  // namespace

void save_nifti(const std::filesystem::path& path, const Volume& volume) {
    check_savable(path, volume);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write NIfTI file " + quoted(path));
    const std::vector<unsigned char> header = header_bytes(volume);
    out.write(reinterpret_cast<const char*>(header.data()), static_cast<std::streamsize>(header.size()));
    std::vector<unsigned char> chunk(kChunkBytes);
    for (std::size_t done = 0; done < volume.values.size();) {
        const std::size_t n = std::min(volume.values.size() - done, chunk.size() / sizeof(float));
        for (std::size_t i = 0; i < n; ++i) store_uint(bits_of(volume.values[done + i]), chunk.data() + 4 * i, 4);
        out.write(reinterpret_cast<const char*>(chunk.data()), static_cast<std::streamsize>(n * sizeof(float)));
        done += n;
    }
    out.close();
    if (!out) throw Error("cannot write NIfTI file " + quoted(path) + ": write error");
}

}  // namespace gsv
