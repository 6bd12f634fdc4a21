#!/usr/bin/env python3
"""Writes data/meshes/teapot.obj: the Utah teapot, tessellated from the 28 bicubic Bezier patches that
Debian's geomview package ships as /usr/share/geomview/geom/teapot.bez.

Usage:
    scripts/make_mesh_data.py [SOURCE] [--segments N] [--output PATH]

SOURCE is teapot.bez itself or a geomview .deb (read with dpkg-deb, so the package need not be
installed: `apt-get download geomview` fetches it). Without SOURCE the installed file is used.

The output is y-up with the body's axis on the y axis and its base at y = 0, spout toward +x. Each patch
is cut into N x N quads (default 16, about 14k triangles). Positions on shared patch edges are welded
so shading is smooth across seams; a vertex's normal is the average of the exact surface normals of
the patches meeting there. Texture coordinates are each patch's own (u, v), the classic teapot
mapping. Python 3 standard library only.
"""

import argparse
import math
import subprocess
import sys
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parent.parent
INSTALLED_SOURCE = Path("/usr/share/geomview/geom/teapot.bez")
SOURCE_IN_DEB = "./usr/share/geomview/geom/teapot.bez"

# Where the source puts the teapot: scale 1/4 of Newell's units, body axis at x = 0.5, y = 0, base at
# z = 0.300049, z up. Checked against the data in read_patches so a different file cannot pass silently.
SOURCE_AXIS_X = 0.5
SOURCE_BASE_Z = 0.300049

WELD_TOLERANCE = 1e-7
CREASE_COSINE = math.cos(math.radians(45.0))


def read_source_text(source):
    if source.suffix == ".deb":
        tar = subprocess.run(["dpkg-deb", "--fsys-tarfile", str(source)], check=True, capture_output=True).stdout
        # tar reads the archive from stdin and writes the one member to stdout.
        return subprocess.run(["tar", "-xO", SOURCE_IN_DEB], input=tar, check=True,
                              capture_output=True).stdout.decode("ascii")
    return source.read_text(encoding="ascii")


def read_patches(text):
    """Returns a list of patches, each 16 control points with u varying fastest, v running upward."""
    words = text.split()
    if not words or words[0] not in ("BBP", "BEZ333"):
        raise SystemExit("make_mesh_data: expected a BBP/BEZ333 header, got %r" % (words[:1],))
    numbers = [float(w) for w in words[1:]]
    if len(numbers) % 48:
        raise SystemExit("make_mesh_data: %d numbers is not a whole number of bicubic patches" % len(numbers))
    points = [tuple(numbers[i:i + 3]) for i in range(0, len(numbers), 3)]
    # geomview lists each patch's rows with v running down the body, so d/du x d/dv points inward.
    # Reversing the rows makes v run upward: the patches then face outward and textures stand upright.
    patches = [[points[first + 4 * (3 - row) + column] for row in range(4) for column in range(4)]
               for first in range(0, len(points), 16)]
    zs = [p[2] for p in points]
    if abs(min(zs) - SOURCE_BASE_Z) > 1e-6:
        raise SystemExit("make_mesh_data: base at z = %g, expected %g; is this geomview's teapot?"
                         % (min(zs), SOURCE_BASE_Z))
    return patches


def bernstein(t):
    s = 1.0 - t
    return (s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t)


def bernstein_derivative(t):
    s = 1.0 - t
    return (-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t)


def combine(patch, weights_u, weights_v):
    x = y = z = 0.0
    for j in range(4):
        for i in range(4):
            w = weights_u[i] * weights_v[j]
            px, py, pz = patch[4 * j + i]
            x += w * px
            y += w * py
            z += w * pz
    return (x, y, z)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def normalized(a):
    length = math.sqrt(dot(a, a))
    return (a[0] / length, a[1] / length, a[2] / length)


def surface_normal(patch, u, v):
    """Unnormalized d/du x d/dv; zero where a patch edge collapses to a point (the lid's knob top)."""
    du = combine(patch, bernstein_derivative(u), bernstein(v))
    dv = combine(patch, bernstein(u), bernstein_derivative(v))
    return cross(du, dv)


def limit_normal(patch, u, v):
    normal = surface_normal(patch, u, v)
    if dot(normal, normal) > 1e-18:
        return normalized(normal)
    # At a collapsed edge the normal is only defined as a limit: step a little into the patch.
    step = 1e-4
    u2 = u + step if u < 0.5 else u - step
    v2 = v + step if v < 0.5 else v - step
    return normalized(surface_normal(patch, u2, v2))


class Welder:
    """Gives one index to samples closer than WELD_TOLERANCE whose normals agree. Patches evaluated
    along a shared edge in opposite directions agree only to rounding, so exact matching would leave
    cracks in the shading; the normal test keeps creases sharp where one piece merely touches another
    (the handle's lower end lands exactly on a corner of the body's patches)."""

    def __init__(self):
        self.cells = {}
        self.points = []
        self.first_normals = []

    def index(self, point, normal):
        cell = tuple(math.floor(c / (16 * WELD_TOLERANCE)) for c in point)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for candidate in self.cells.get((cell[0] + dx, cell[1] + dy, cell[2] + dz), ()):
                        d = sub(self.points[candidate], point)
                        if (dot(d, d) <= WELD_TOLERANCE * WELD_TOLERANCE
                                and dot(self.first_normals[candidate], normal) > CREASE_COSINE):
                            return candidate
        self.points.append(point)
        self.first_normals.append(normal)
        self.cells.setdefault(cell, []).append(len(self.points) - 1)
        return len(self.points) - 1


def to_output_frame(p):
    """Source z-up to y-up (a rotation, so handedness and winding are kept), axis and base to the origin."""
    x, y, z = p
    return (x - SOURCE_AXIS_X, z - SOURCE_BASE_Z, -y)


def rotate_vector(n):
    x, y, z = n
    return (x, z, -y)


def tessellate(patches, segments):
    welder = Welder()
    normal_sums = []
    triangles = []  # per triangle: ((position, texcoord) per corner), texcoord indexes the shared grid
    for patch in patches:
        grid = []
        for j in range(segments + 1):
            v = j / segments
            for i in range(segments + 1):
                u = i / segments
                position = to_output_frame(combine(patch, bernstein(u), bernstein(v)))
                n = rotate_vector(limit_normal(patch, u, v))
                index = welder.index(position, n)
                if index == len(normal_sums):
                    normal_sums.append((0.0, 0.0, 0.0))
                s = normal_sums[index]
                normal_sums[index] = (s[0] + n[0], s[1] + n[1], s[2] + n[2])
                grid.append(index)
        row = segments + 1
        for j in range(segments):
            for i in range(segments):
                a = j * row + i
                b, c, d = a + 1, a + row + 1, a + row
                for corners in ((a, b, c), (a, c, d)):
                    if len({grid[k] for k in corners}) == 3:  # drop the slivers at collapsed edges
                        triangles.append(tuple((grid[k], k) for k in corners))
    normals = [normalized(s) for s in normal_sums]
    return welder.points, normals, triangles


def check_winding(positions, triangles):
    """Stops unless every patch faces outward. Neighbouring triangles must cross their shared edge in
    opposite directions (consistent winding), and each connected piece (body, lid, spout, handle) must
    enclose positive volume around its own centroid, which holds for outward-facing, roughly convex
    shells and tubes. The source's patch order is meant to guarantee both; this catches a different file."""
    directed = set()
    for triangle in triangles:
        corners = [corner[0] for corner in triangle]
        for k in range(3):
            edge = (corners[k], corners[(k + 1) % 3])
            if edge in directed:
                raise SystemExit("make_mesh_data: two triangles wind the same way along edge %s" % (edge,))
            directed.add(edge)

    parent = list(range(len(positions)))

    def root(k):
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    for triangle in triangles:
        for corner in triangle[1:]:
            parent[root(corner[0])] = root(triangle[0][0])
    pieces = {}
    for triangle in triangles:
        pieces.setdefault(root(triangle[0][0]), []).append(triangle)
    for piece in pieces.values():
        used = {corner[0] for triangle in piece for corner in triangle}
        centroid = [sum(positions[k][axis] for k in used) / len(used) for axis in range(3)]
        outwardness = 0.0
        for triangle in piece:
            p = [positions[corner[0]] for corner in triangle]
            middle = [(p[0][axis] + p[1][axis] + p[2][axis]) / 3.0 for axis in range(3)]
            outwardness += dot(cross(sub(p[1], p[0]), sub(p[2], p[0])), sub(middle, centroid))
        if outwardness <= 0.0:
            raise SystemExit("make_mesh_data: a piece of %d triangles faces inward" % len(piece))
    return len(pieces)


def format_vector(vector):
    # Values within rounding of zero on the negative side would print as "-0.000000".
    return " ".join("%.6f" % c if "%.6f" % c != "-0.000000" else "0.000000" for c in vector)


def write_obj(path, positions, normals, triangles, segments, source_name):
    grid = [(i / segments, j / segments) for j in range(segments + 1) for i in range(segments + 1)]
    lines = [
        "# Utah teapot (Martin Newell, 1975): the 28 Bezier patches of %s from Debian's geomview" % source_name,
        "# package, tessellated %dx%d per patch by scripts/make_mesh_data.py. Open at the bottom like" % (
            segments, segments),
        "# the original data; y up, base at y = 0. %d vertices, %d triangles." % (len(positions), len(triangles)),
        "o teapot",
    ]
    lines += ["v " + format_vector(p) for p in positions]
    lines += ["vn " + format_vector(n) for n in normals]
    lines += ["vt %.6g %.6g" % t for t in grid]
    lines += ["f " + " ".join("%d/%d/%d" % (p + 1, t + 1, p + 1) for p, t in triangle) for triangle in triangles]
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n", encoding="ascii")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("source", nargs="?", type=Path, default=INSTALLED_SOURCE,
                        help="teapot.bez or a geomview .deb (default: %s)" % INSTALLED_SOURCE)
    parser.add_argument("--segments", type=int, default=16, help="quads per patch edge (default 16)")
    parser.add_argument("--output", type=Path, default=REPO_ROOT / "data" / "meshes" / "teapot.obj")
    args = parser.parse_args()
    if args.segments < 1:
        raise SystemExit("make_mesh_data: --segments must be at least 1, got %d" % args.segments)
    if not args.source.exists():
        raise SystemExit("make_mesh_data: %s not found; run `apt-get download geomview` and pass the .deb"
                         % args.source)

    patches = read_patches(read_source_text(args.source))
    positions, normals, triangles = tessellate(patches, args.segments)
    pieces = check_winding(positions, triangles)
    write_obj(args.output, positions, normals, triangles, args.segments, INSTALLED_SOURCE.name)
    print("make_mesh_data: wrote %s (%d patches in %d pieces, %d vertices, %d triangles)"
          % (args.output, len(patches), pieces, len(positions), len(triangles)))


if __name__ == "__main__":
    sys.exit(main())
