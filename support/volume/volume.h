#pragma once
// A scalar volume as lab 06 uploads it as a 3D texture, and the CPU's emulation of the texture's
// GL_LINEAR, GL_CLAMP_TO_EDGE lookup: the reference a GPU raycaster's samples are checked against.
//
// Voxel (i, j, k) is the texel whose centre is at texture coordinate ((i + 0.5) / nx, (j + 0.5) / ny,
// (k + 0.5) / nz), and at the physical point ((i + 0.5) sx, (j + 0.5) sy, (k + 0.5) sz) of the box
// [0, extent()]: a voxel's value stands for the centre of its cell, as a texel's does in GL.
//
// The emulation is the filter as the GL specification states it (section 8.14.2 of GL 4.6) with exact
// weights. Hardware rounds the weights to a few fractional bits (8 on NVIDIA, per the CUDA programming
// guide's texture fetching appendix), so a GPU sample can differ from sample() by about 1/512 of the
// difference between neighbouring voxels; compare with that in mind (support/particles/particle_grid.h does the same).
#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace gsv {

// GL 4.x guarantees 3D textures of at least 2048 texels a side (MAX_3D_TEXTURE_SIZE), and 2^28 voxels are
// 1 GiB of float32: bounds, so a corrupt header is refused before it allocates anything.
inline constexpr int kMaxVolumeSide = 2048;
inline constexpr std::size_t kMaxVolumeVoxels = std::size_t(1) << 28;

struct Volume {
    int nx = 0, ny = 0, nz = 0;
    // Physical distance between neighbouring voxel centres along x, y and z (mm for medical data, domain
    // units for generated data). Anisotropic spacing is common: MRI slices are often thicker than their
    // pixels, and a raycaster that treats voxels as cubes squashes the anatomy and tilts every gradient.
    glm::dvec3 spacing{1.0, 1.0, 1.0};
    // nx * ny * nz values, x fastest, then y, then z: the layout glTexImage3D takes with GL_RED and
    // GL_FLOAT, voxel (i, j, k) at (k ny + j) nx + i.
    std::vector<float> values;
    // The range normalized() maps onto [0, 1]. Readers and generators set it to the smallest and largest
    // value (update_range()); a caller may narrow it to a window of interest.
    float min = 0, max = 0;
    std::string name;  // what messages and window titles call the volume: a file's stem, a generator's name

    // Position of voxel (i, j, k) in `values`, and its value. Throw gsv::Error outside the grid or when
    // `values` does not hold nx * ny * nz values.
    std::size_t index(int i, int j, int k) const;
    float at(int i, int j, int k) const;

    // Physical size of the box the voxels tile: (nx sx, ny sy, nz sz). Each voxel is a cell of the box, so
    // this is n times the spacing, not (n - 1) times it.
    glm::dvec3 extent() const;

    // Sets min and max to the smallest and largest value (0 and 0 for no values). The values must be finite.
    void update_range();

    // Sets min and max to the values below which low_share and high_share of the voxels lie (nearest rank), the
    // window a viewer opens a scan with: a few outliers (an MRI's brightest voxels) then saturate rather than squeeze
    // all the tissue into a sliver of [0, 1] when normalized(). Throws gsv::Error unless 0 <= low_share <
    // high_share <= 1, or for no values.
    void set_percentile_window(double low_share, double high_share);

    // A copy with each value mapped by (v - min) / (max - min), computed in double, clamped to [0, 1] (a
    // narrowed window saturates as an 8-bit texture would); min becomes 0 and max 1. A constant volume
    // (max == min) maps to 0, not to 0/0 = NaN, and keeps min = max = 0. Throws gsv::Error for a min or
    // max that is not finite or max < min.
    Volume normalized() const;

    // The same voxels with the y and z axes exchanged: voxel (i, j, k) becomes (i, k, j), and the spacing follows.
    // A scan whose k runs from the feet up is then drawn upright in a y-up world. Exchanging two axes mirrors, so a
    // scan drawn unmirrored before is mirrored after and the other way round (lab 06's volume source says which).
    Volume with_y_and_z_exchanged() const;

    // What GL_LINEAR with GL_CLAMP_TO_EDGE returns at texture coordinate s in [0,1]^3, in double from the
    // float values: per axis x = s n - 1/2 clamped to [0, n - 1], i0 = floor(x), f = x - i0, then the
    // trilinear mix of voxels i0 and i0 + 1. So a texel centre gives that voxel exactly, and the outer half
    // texel, or anything outside [0,1], the edge voxel. An x within 2^-30 texel of a centre counts as the
    // centre: (i + 0.5) / n rounded to double lands up to about n 1e-16 texel off it, and the exact voxel
    // is what a reference must return there (hardware resolves 1/256 texel at best). A NaN coordinate
    // gives NaN. Throws gsv::Error for a volume without nx * ny * nz values.
    double sample(glm::dvec3 texcoord) const;
};

}  // namespace gsv
