#!/usr/bin/env python3
"""Writes data/volumes/marschner_lobb_thick_slices.nii: the Marschner-Lobb test signal on thick slices,
41 x 41 x 8 voxels of 1 x 1 x 2.5 mm, a little-endian float32 NIfTI-1 file.

Usage:
    scripts/make_volume_data.py [--output PATH]

Lab 06's other volumes have cubic voxels (the Marschner-Lobb grid, the MRI head's 2 mm), on which a gradient
that ignores the voxel spacing points the right way, only longer. Here a slice is 2.5 times as thick as a voxel
is wide, and the box is 41 x 41 x 20 mm, so a gradient taken per voxel instead of per millimetre, or light and
view directions taken in texture space, bend the normals (the lab sheet's case 'spacing' and 'phong-slices').

The signal is gsv::marschner_lobb (support/volume/marschner_lobb.cpp) with f_M = 6 and alpha = 0.25, in its
own units of 20.5 mm (so x and y span [-1, 1] as in the kit's generated volume): voxel (i, j, k) holds its value
at x = (i + 0.5) / 20.5 - 1, y likewise, z = ((k + 0.5) 2.5 - 10) / 20.5, the voxel's centre. Python 3 standard
library only; the file is byte for byte the same wherever libm rounds sin and cos the same (float32 absorbs a
last-bit difference nearly always).
"""

import argparse
import math
import struct
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parent.parent
OUTPUT = REPO_ROOT / "data" / "volumes" / "marschner_lobb_thick_slices.nii"

NX, NY, NZ = 41, 41, 8
SPACING_MM = (1.0, 1.0, 2.5)
MM_PER_UNIT = NX * SPACING_MM[0] / 2  # x spans [-1, 1] of the signal's units
F_M, ALPHA = 6.0, 0.25


def marschner_lobb(x, y, z):
    r = math.hypot(x, y)
    rho_r = math.cos(2 * math.pi * F_M * math.cos(math.pi * r / 2))
    return (1 - math.sin(math.pi * z / 2) + ALPHA * (1 + rho_r)) / (2 * (1 + ALPHA))


def centre(index, count, spacing):
    """The voxel centre's coordinate in the signal's units, the box centred on 0."""
    return ((index + 0.5) * spacing - count * spacing / 2) / MM_PER_UNIT


def header():
    h = bytearray(352)  # the 348-byte header, then 4 zero bytes: no extensions
    struct.pack_into("<i", h, 0, 348)  # sizeof_hdr
    struct.pack_into("<8h", h, 40, 3, NX, NY, NZ, 1, 1, 1, 1)  # dim
    struct.pack_into("<hh", h, 70, 16, 32)  # datatype float32, bitpix
    struct.pack_into("<8f", h, 76, 1.0, *SPACING_MM, 0, 0, 0, 0)  # pixdim (qfac 1)
    struct.pack_into("<fff", h, 108, 352.0, 1.0, 0.0)  # vox_offset, scl_slope, scl_inter
    h[123] = 2  # xyzt_units: millimetres
    description = b"Marschner-Lobb f_M 6 alpha 0.25, 1 x 1 x 2.5 mm"
    h[148:148 + len(description)] = description
    h[344:348] = b"n+1\x00"
    return bytes(h)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", type=Path, default=OUTPUT)
    args = parser.parse_args()
    voxels = bytearray()
    for k in range(NZ):  # x fastest, then y, then z
        z = centre(k, NZ, SPACING_MM[2])
        for j in range(NY):
            y = centre(j, NY, SPACING_MM[1])
            for i in range(NX):
                voxels += struct.pack("<f", marschner_lobb(centre(i, NX, SPACING_MM[0]), y, z))
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_bytes(header() + bytes(voxels))
    print("%s: %d x %d x %d voxels of %g x %g x %g mm, %d bytes" % (args.output, NX, NY, NZ, *SPACING_MM,
                                                                   352 + len(voxels)))


if __name__ == "__main__":
    main()
