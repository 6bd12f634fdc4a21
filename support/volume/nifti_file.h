#pragma once
// NIfTI-1 volumes (.nii), the format of MRI and CT data in neuroimaging: a 348-byte binary header, 4
// extension-flag bytes, optional extensions, then the voxels from vox_offset on, x fastest, then y, then z,
// which is already the order glTexImage3D takes. Header and voxels are in the byte order of whoever wrote
// them, which the header does not state: a reader finds it by reading sizeof_hdr, 348, both ways.
//
// Read: single-file .nii (magic "n+1") and the same gzipped (.nii.gz, told by its gzip magic, not its name;
// decompressed through zlib, at most 2 GiB), either byte order, datatypes uint8, int8, int16, uint16, int32,
// float32 and float64, one 3D volume (dim[0] = 3, or 4 with dim[4] = 1). Not read: .hdr/.img pairs (magic "ni1"),
// NIfTI-2, complex and RGB voxels, time series. The orientation (qform,
// sform) is ignored: the volume is shown in its own voxel axes, with its spacing.
#include "support/volume/volume.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>

namespace gsv {

struct NiftiHeader {
    int nx = 0, ny = 0, nz = 0;
    int datatype = 0;         // the NIfTI code: 2 uint8, 4 int16, 8 int32, 16 float32, 64 float64, 256 int8, 512 uint16
    int bits_per_voxel = 0;   // bitpix
    bool big_endian = false;  // the byte order of header and voxels
    // pixdim[1..3] converted to millimetres by xyzt_units (metres and microns are scaled; mm and an unknown
    // unit are taken as they are).
    glm::dvec3 spacing{1.0, 1.0, 1.0};
    std::uint64_t vox_offset = 0;
    // Stored values v become scl_slope v + scl_inter when `scaled`, i.e. when scl_slope is finite and not 0
    // (the standard's rule: 0 or NaN means the values are stored unscaled).
    double scl_slope = 0, scl_inter = 0;
    bool scaled = false;
    std::string description;  // descrip, up to its first NUL
};

// "int16" for 4, and so on for the types above; "complex64", "rgb24", ... or "unknown" for the others.
const char* nifti_datatype_name(int code);

// Reads and checks the header alone, and that the file holds exactly the voxels it promises. Throws
// gsv::Error with one line naming the file for: a missing or unreadable file, one too short for the
// header, corrupt or cut-short gzip data, one that is not NIfTI-1 (saying so when it looks like a .hdr/.img pair or
// NIfTI-2),
// a dim, datatype (naming its code), bitpix, pixdim[1..3] (not finite and positive), vox_offset or
// scl_inter it cannot use, and a voxel block of another size ("expected N bytes of voxels after offset O,
// found M"). Nothing is allocated from the header's sizes before the file's size has confirmed them.
NiftiHeader read_nifti_header(const std::filesystem::path& path);

// The volume in float32, scaled by scl_slope and scl_inter when the header says so (computed in double,
// rounded once), min and max set to its range, named after the file's stem. int32 values above 2^24 lose
// their lowest bits in float32, as they would in the texture. Throws gsv::Error as read_nifti_header does,
// and for a voxel that is NaN or infinite, or becomes so in float32 ("voxel (i, j, k) is NaN").
Volume load_nifti(const std::filesystem::path& path);

// Writes `volume` as a little-endian float32 single-file .nii: vox_offset 352, no scaling, spacing as
// pixdim[1..3] in millimetres (rounded to float32), qform_code 1 with an identity rotation, and "gsv <name>"
// as the description. load_nifti reads back the same values bit for bit. Throws gsv::Error, before
// creating the file, for a volume it cannot write (a size outside 1..kMaxVolumeSide, a value count that is
// not nx ny nz, a spacing that is not positive and finite in float32, a NaN or infinite value), or if the
// file cannot be written.
void save_nifti(const std::filesystem::path& path, const Volume& volume);

}  // namespace gsv
