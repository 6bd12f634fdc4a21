#!/usr/bin/env python3
"""Writes data/terrain/*.height, lab 04's real elevation models, from the two digital elevation models that
Debian's python-matplotlib-data package ships:

    jacksboro_fault_dem.npz  ->  data/terrain/jacksboro_fault.height   (land, 403 x 344 samples)
    topobathy.npz            ->  data/terrain/topobathy.height         (land and sea floor, 120 x 91 samples)

Usage:
    scripts/convert-dem.py [--source-dir DIR] [--output-dir DIR]
    scripts/convert-dem.py --check

--check converts into a temporary folder and compares the result byte for byte with the files in data/terrain
(or --output-dir):
exit 0 when they match, 1 (with one line saying which file and where) when they differ, 77 when
python-matplotlib-data is not installed, so ctest reports the check as skipped rather than failed.

The .height format, the units and the row order are described in data/README.md ("Terrains"). In short: the
ASCII line "GSVHEIGHT 1 <width> <height> <dx_m> <dy_m>\\n", then width*height little-endian float32 heights in
metres, row-major, row 0 = the SOUTH row. Python 3 standard library only: .npz is a zip of .npy files, and the
.npy header is a Python dict literal, so neither needs numpy.
"""

import argparse
import ast
import math
import struct
import sys
import tempfile
import zipfile
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parent.parent
DEFAULT_SOURCE_DIR = Path("/usr/share/matplotlib/mpl-data/sample_data")
DEFAULT_OUTPUT_DIR = REPO_ROOT / "data" / "terrain"
SKIP = 77

# WGS84 (NIMA TR8350.2): semi-major axis and flattening.
WGS84_A = 6378137.0
WGS84_F = 1.0 / 298.257223563
WGS84_E2 = WGS84_F * (2.0 - WGS84_F)

# Spacings are rounded to a millimetre: far finer than either model's accuracy, and coarse enough that a libm
# whose sin or cos differed in the last bit still writes the same header, so --check stays byte-exact.
SPACING_DECIMALS = 3


def fail(message):
    raise SystemExit("convert-dem: " + message)


# ---------------------------------------------------------------------------------------------------------
# Reading .npz / .npy without numpy

def read_npy(blob, name):
    """Returns (descr, shape, data bytes) of one .npy file (format versions 1 to 3)."""
    if blob[:6] != b"\x93NUMPY":
        fail("%s is not a .npy file" % name)
    major = blob[6]
    if major == 1:
        (header_len,), start = struct.unpack("<H", blob[8:10]), 10
    elif major in (2, 3):
        (header_len,), start = struct.unpack("<I", blob[8:12]), 12
    else:
        fail("%s: .npy format version %d is not supported" % (name, major))
    header = ast.literal_eval(blob[start:start + header_len].decode("latin1"))
    if header.get("fortran_order"):
        fail("%s is stored in Fortran order; only C order is supported" % name)
    data = blob[start + header_len:]
    count = math.prod(header["shape"])
    if header["descr"] not in STRUCT_CODES:
        fail("%s holds %s values; only %s are supported" % (name, header["descr"], ", ".join(STRUCT_CODES)))
    size = struct.calcsize("<" + STRUCT_CODES[header["descr"]])
    if len(data) != count * size:
        fail("%s: expected %d bytes of data for shape %s, found %d" % (name, count * size, header["shape"], len(data)))
    return header["descr"], tuple(header["shape"]), data


def read_npz(path, expected):
    """Returns {array name: (descr, shape, data)} and insists on exactly the arrays in `expected`
    (name -> (descr, number of dimensions)), so a changed source cannot be converted by guesswork."""
    with zipfile.ZipFile(path) as archive:
        arrays = {Path(info.filename).stem: read_npy(archive.read(info), "%s:%s" % (path.name, info.filename))
                  for info in archive.infolist()}
    if set(arrays) != set(expected):
        fail("%s holds %s, expected %s" % (path, sorted(arrays), sorted(expected)))
    for key, (descr, dims) in expected.items():
        if arrays[key][0] != descr or len(arrays[key][1]) != dims:
            fail("%s: '%s' is %s of shape %s, expected %s with %d dimensions"
                 % (path, key, arrays[key][0], arrays[key][1], descr, dims))
    return arrays


STRUCT_CODES = {"<i2": "h", "<f4": "f", "<f8": "d"}


def values(array):
    descr, shape, data = array
    return struct.unpack("<%d%s" % (math.prod(shape), STRUCT_CODES[descr]), data)


def scalar(array):
    (value,) = values(array)
    return value


# ---------------------------------------------------------------------------------------------------------
# Geodesy

def metres_per_radian(latitude_deg):
    """(east, north) ground metres per radian of longitude and of latitude on the WGS84 ellipsoid: the
    prime-vertical radius of curvature times cos(latitude), and the meridional radius of curvature."""
    phi = math.radians(latitude_deg)
    w2 = 1.0 - WGS84_E2 * math.sin(phi) ** 2
    east = WGS84_A / math.sqrt(w2) * math.cos(phi)
    north = WGS84_A * (1.0 - WGS84_E2) / (w2 * math.sqrt(w2))
    return east, north


def ground_spacing(latitude_deg, dlon_deg, dlat_deg):
    east, north = metres_per_radian(latitude_deg)
    return (round(east * math.radians(dlon_deg), SPACING_DECIMALS),
            round(north * math.radians(dlat_deg), SPACING_DECIMALS))


# ---------------------------------------------------------------------------------------------------------
# The two models

def jacksboro(source_dir):
    """int16 metres, 3 arc-second grid; rows run from the north edge ('ymin' = 36.733 N) to the south edge
    ('ymax' = 36.446 N), so they are reversed to put the south row first."""
    path = source_dir / "jacksboro_fault_dem.npz"
    arrays = read_npz(path, {"elevation": ("<i2", 2), "dx": ("<f8", 0), "dy": ("<f8", 0), "xmin": ("<f8", 0),
                             "xmax": ("<f8", 0), "ymin": ("<f8", 0), "ymax": ("<f8", 0)})
    rows, columns = arrays["elevation"][1]
    dx, dy = scalar(arrays["dx"]), scalar(arrays["dy"])
    xmin, xmax, ymin, ymax = (scalar(arrays[k]) for k in ("xmin", "xmax", "ymin", "ymax"))
    # The bounds are cell edges in degrees: they span exactly columns * dx and rows * dy.
    if abs((xmax - xmin) / dx - columns) > 1e-6:
        fail("%s: (xmax - xmin) / dx = %r, not the %d columns" % (path, (xmax - xmin) / dx, columns))
    if abs((ymin - ymax) / dy - rows) > 1e-6:
        fail("%s: (ymin - ymax) / dy = %r, not the %d rows; expected 'ymin' to be the north (first row) edge"
             % (path, (ymin - ymax) / dy, rows))
    elevation = values(arrays["elevation"])
    south_first = [elevation[r * columns:(r + 1) * columns] for r in reversed(range(rows))]
    heights = b"".join(struct.pack("<%df" % columns, *row) for row in south_first)
    dx_m, dy_m = ground_spacing((ymin + ymax) / 2.0, dx, dy)
    return columns, rows, dx_m, dy_m, heights


def topobathy(source_dir):
    """float32 metres (negative below sea level) on a Mercator grid: even steps of longitude, and latitudes
    increasing with the row, so row 0 is already the south row and the bytes are copied unchanged."""
    path = source_dir / "topobathy.npz"
    arrays = read_npz(path, {"topo": ("<f4", 2), "longitude": ("<f4", 1), "latitude": ("<f4", 1)})
    rows, columns = arrays["topo"][1]
    lon, lat = values(arrays["longitude"]), values(arrays["latitude"])
    if len(lon) != columns or len(lat) != rows:
        fail("%s: %d longitudes and %d latitudes for %d x %d heights" % (path, len(lon), len(lat), columns, rows))
    if any(b <= a for a, b in zip(lon, lon[1:])) or any(b <= a for a, b in zip(lat, lat[1:])):
        fail("%s: longitudes and latitudes must both increase (west to east, south to north)" % path)
    dlon = (lon[-1] - lon[0]) / (columns - 1)
    # Steps in Mercator y, in degrees, equal the longitude step: the cells are square on the map. Checked
    # (to the float32 rounding of the stored latitudes) because data/README.md's scale argument rests on it.
    mercator = [math.degrees(math.log(math.tan(math.pi / 4 + math.radians(p) / 2))) for p in lat]
    worst = max(abs((b - a) / dlon - 1.0) for a, b in zip(mercator, mercator[1:]))
    if worst > 2e-3:
        fail("%s: latitude steps are not even in Mercator y (off by %.2g); see data/README.md" % (path, worst))
    dlat = (lat[-1] - lat[0]) / (rows - 1)
    dx_m, dy_m = ground_spacing((lat[0] + lat[-1]) / 2.0, dlon, dlat)
    return columns, rows, dx_m, dy_m, arrays["topo"][2]


MODELS = {"jacksboro_fault.height": jacksboro, "topobathy.height": topobathy}


# ---------------------------------------------------------------------------------------------------------
# Writing

def shortest_text(value):
    """The shortest %g text that reads back as `value`: what the kit's C++ writer (save_height_field)
    writes too, so a file it rewrites is byte-for-byte the same."""
    for digits in range(1, 18):
        text = "%.*g" % (digits, value)
        if float(text) == value:
            return text
    return repr(value)


def height_file_bytes(width, height, dx_m, dy_m, heights):
    for name, count in (("width", width), ("height", height)):
        if not 1 <= count <= 8192:
            fail("%s %d is outside 1..8192" % (name, count))
    floats = struct.unpack("<%df" % (width * height), heights)
    bad = next((i for i, h in enumerate(floats) if not math.isfinite(h)), None)
    if bad is not None:
        fail("height at sample (%d, %d) is %r" % (bad % width, bad // width, floats[bad]))
    header = "GSVHEIGHT 1 %d %d %s %s\n" % (width, height, shortest_text(dx_m), shortest_text(dy_m))
    return header.encode("ascii") + heights


def convert(source_dir, output_dir):
    output_dir.mkdir(parents=True, exist_ok=True)
    for name, model in MODELS.items():
        width, height, dx_m, dy_m, heights = model(source_dir)
        (output_dir / name).write_bytes(height_file_bytes(width, height, dx_m, dy_m, heights))
        floats = struct.unpack("<%df" % (width * height), heights)
        print("%s: %d x %d samples, %s m x %s m apart, heights %g .. %g m"
              % (name, width, height, shortest_text(dx_m), shortest_text(dy_m), min(floats), max(floats)))


def first_difference(a, b):
    return next((i for i, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))


def check(source_dir, committed_dir):
    with tempfile.TemporaryDirectory() as tmp:
        convert(source_dir, Path(tmp))
        for name in MODELS:
            committed = committed_dir / name
            fresh = (Path(tmp) / name).read_bytes()
            if not committed.is_file():
                print("convert-dem: %s is missing; rebuild it with scripts/convert-dem.py" % committed, file=sys.stderr)
                return 1
            old = committed.read_bytes()
            if old != fresh:
                print("convert-dem: %s differs from its regeneration at byte %d (%d bytes committed, %d "
                      "regenerated); if the change is meant, rebuild it with scripts/convert-dem.py"
                      % (committed, first_difference(old, fresh), len(old), len(fresh)),
                      file=sys.stderr)
                return 1
    print("%s: the .height files match their regeneration from python-matplotlib-data" % committed_dir)
    return 0


def main():
    parser = argparse.ArgumentParser(
        description="Converts python-matplotlib-data's elevation models into data/terrain/*.height "
                    "(details in the script's docstring and data/README.md).")
    parser.add_argument("--source-dir", type=Path, default=DEFAULT_SOURCE_DIR,
                        help="folder with the .npz files (default: python-matplotlib-data's sample_data)")
    parser.add_argument("--output-dir", type=Path, default=DEFAULT_OUTPUT_DIR, help="default: data/terrain")
    parser.add_argument("--check", action="store_true",
                        help="compare a fresh conversion with the files in the output folder instead of writing them")
    args = parser.parse_args()
    missing = [n for n in ("jacksboro_fault_dem.npz", "topobathy.npz") if not (args.source_dir / n).is_file()]
    if missing:
        print("convert-dem: %s not found in %s (Debian package python-matplotlib-data not installed?)%s"
              % (" and ".join(missing), args.source_dir, "; check skipped" if args.check else ""), file=sys.stderr)
        return SKIP if args.check else 1
    if args.check:
        return check(args.source_dir, args.output_dir)
    convert(args.source_dir, args.output_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
