#!/usr/bin/env python3
"""Helpers to drive the real MeshLab host (meshlabserver 2020.09) from Python.

Used by the host integration tests (test_host.py) and by scripts/run.sh's headless demo.
No third-party modules: PLY reading/writing, .mlx script writing and the meshlabserver
runner are all here.

    python3 mlhost.py summary OUT.ply ...   # prints quality range / selection of saved PLYs
    python3 mlhost.py seeds ENERGY.ply [K]  # K far-apart feature vertices, "i, j, k"
    python3 mlhost.py mlx OUT.mlx 'FILTER' NAME=VALUE ... [-- 'FILTER' NAME=VALUE ...]
                                            # writes a .mlx (ints, floats, true/false, text)
"""

import math
import json
import os
import shutil
import struct
import subprocess
import tempfile
import sys
import unittest
from xml.sax.saxutils import quoteattr

FILTER_ENERGY = "Compute Geometric Snake Feature Energy"
FILTER_SEED_PATH = "Geometric Snake Seed Path"
FILTER_SNAKE = "Geometric Snake from Seed Vertices"
FILTER_CUT = "Cut Mesh along Geometric Snake"
FILTER_EXPORT = "Export Geometric Snake Curves"
SELECTED = 0x0020  # vcg vertex BitFlags::SELECTED, saved as the PLY "flags" property

# ---------------------------------------------------------------------------- .mlx
STRINGS = {"Seeds", "SeedPoints", "SeedFile", "OutputFile", "CurveFile"}
ENUMS = {
    "EnergyType": ["Normal variation", "Curvature norm", "Quadric error", "Crease distance (CAD)",
                   "Part boundary (concave)"],
    "Cost": ["Length", "Feature"],
    "Method": ["Local embedding (paper)", "3D update + projection"],
    "Which": ["All snakes", "Selected snake"],
    "Mode": ["Select", "Select only (mesh unchanged)", "Split in two", "Cut open"],
    "Side": ["Smaller part", "Larger part", "Inside", "Outside"],
}


def param_xml(name, value):
    """One <Param> element in MeshLab 2020.09 .mlx syntax (see RichParameterAdapter::create)."""
    if name in STRINGS:
        return '<Param type="RichString" name="%s" value=%s/>' % (name, quoteattr(str(value)))
    if name in ENUMS:
        labels = ENUMS[name]
        extra = "".join(' enum_val%d=%s' % (i, quoteattr(l)) for i, l in enumerate(labels))
        return '<Param type="RichEnum" name="%s" value="%d" enum_cardinality="%d"%s/>' % (
            name, int(value), len(labels), extra)
    if isinstance(value, bool):
        return '<Param type="RichBool" name="%s" value="%s"/>' % (name, "true" if value else "false")
    if isinstance(value, int):
        return '<Param type="RichInt" name="%s" value="%d"/>' % (name, value)
    if isinstance(value, float):
        return '<Param type="RichFloat" name="%s" value="%r"/>' % (name, value)
    return '<Param type="RichString" name="%s" value=%s/>' % (name, quoteattr(str(value)))


# Defaults of the parameters added after the first scripts were written: meshlabserver 2020.09
# aborts on a script that omits any parameter of a filter, so write_mlx fills these in.
DEFAULTS = {
    FILTER_ENERGY: {"CreaseAngle": 30.0, "MergeDuplicateVertices": False},
    FILTER_SEED_PATH: {"SeedPoints": "", "SeedFile": "", "MergeDuplicateVertices": False},
    FILTER_SNAKE: {"SeedPoints": "", "SeedFile": "", "EnergyType": 0, "CreaseAngle": 30.0,
                   "MergeDuplicateVertices": False, "Balloon": 0.0, "TimeLimit": 0.0, "CompleteLoop": False},
    FILTER_CUT: {"CurveFile": "", "SnakeIndex": -1, "Mode": 0, "Side": 0, "Split": False},
}


def write_mlx(path, filters):
    """filters: list of (filter name, {param: value}); parameters not given get DEFAULTS."""
    lines = ["<!DOCTYPE FilterScript>", "<FilterScript>"]
    for name, params in filters:
        lines.append(" <filter name=%s>" % quoteattr(name))
        full = dict(params)
        for k, v in DEFAULTS.get(name, {}).items():
            full.setdefault(k, v)
        for k, v in full.items():
            lines.append("  " + param_xml(k, v))
        lines.append(" </filter>")
    lines.append("</FilterScript>")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


# ---------------------------------------------------------------------------- host
def meshlabserver_cmd(authfile):
    exe = shutil.which("meshlabserver")
    if exe is None:
        raise RuntimeError("meshlabserver not found: apt-get install meshlab")
    xvfb = shutil.which("xvfb-run")
    if xvfb is None:
        raise RuntimeError("xvfb-run not found: apt-get install xvfb xauth")
    # Always a private virtual display: meshlabserver creates a GL context. Our own auth file
    # (-f): xvfb-run's own temporary folder sometimes fails to clean up ("problem while
    # cleaning up temporary directory", exit 5), which would mask meshlabserver's status.
    return [xvfb, "-a", "-f", authfile, "-s", "-screen 0 640x480x24", exe]


def run_meshlabserver(args, timeout=300, cwd=None, reuse_display=False):
    """Runs `xvfb-run -a meshlabserver ARGS`; returns (returncode, combined output).
    A negative returncode means meshlabserver was killed by a signal (a crash).
    reuse_display: run on $DISPLAY when set (a script already under xvfb-run), no Xvfb per run."""
    env = dict(os.environ)
    env.setdefault("LIBGL_ALWAYS_SOFTWARE", "1")
    env.setdefault("XDG_RUNTIME_DIR", "/tmp/runtime-%d" % os.getuid())
    os.makedirs(env["XDG_RUNTIME_DIR"], mode=0o700, exist_ok=True)
    if reuse_display and env.get("DISPLAY"):
        p = subprocess.run([shutil.which("meshlabserver")] + list(args), stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, timeout=timeout, cwd=cwd, env=env)
        return p.returncode, p.stdout.decode("utf-8", "replace")
    with tempfile.TemporaryDirectory(prefix="gs-xauth-", ignore_cleanup_errors=True) as auth:
        p = subprocess.run(meshlabserver_cmd(os.path.join(auth, "Xauthority")) + list(args),
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           stdin=subprocess.DEVNULL, timeout=timeout, cwd=cwd, env=env)
    out = p.stdout.decode("utf-8", "replace")
    rc = p.returncode
    # xvfb-run reports a child killed by signal N as exit status 128+N.
    if rc > 128 and rc != 255:
        rc = -(rc - 128)
    return rc, out


# ---------------------------------------------------------------------------- PLY
_PLY_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


class Ply:
    """elements: {name: list of dicts}, order: element names in file order."""

    def __init__(self):
        self.elements = {}
        self.props = {}
        self.order = []

    @property
    def vertices(self):
        return self.elements.get("vertex", [])

    @property
    def faces(self):
        return self.elements.get("face", [])


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii", "replace").splitlines()
    fmt = None
    ply = Ply()
    counts = {}
    cur = None
    for line in header:
        t = line.split()
        if not t:
            continue
        if t[0] == "format":
            fmt = t[1]
        elif t[0] == "element":
            cur = t[1]
            counts[cur] = int(t[2])
            ply.order.append(cur)
            ply.props[cur] = []
        elif t[0] == "property":
            if t[1] == "list":
                ply.props[cur].append((t[4], ("list", t[2], t[3])))
            else:
                ply.props[cur].append((t[2], t[1]))
    body = data[end:]
    if fmt == "ascii":
        tokens = body.split()
        pos = 0
        for el in ply.order:
            rows = []
            for _ in range(counts[el]):
                row = {}
                for name, typ in ply.props[el]:
                    if isinstance(typ, tuple):
                        n = int(tokens[pos]); pos += 1
                        row[name] = [int(x) for x in tokens[pos:pos + n]]; pos += n
                    else:
                        tok = tokens[pos].decode(); pos += 1
                        row[name] = float(tok) if _PLY_TYPES[typ] in "fd" else int(tok)
                rows.append(row)
            ply.elements[el] = rows
    else:
        endian = "<" if fmt == "binary_little_endian" else ">"
        pos = 0
        for el in ply.order:
            rows = []
            for _ in range(counts[el]):
                row = {}
                for name, typ in ply.props[el]:
                    if isinstance(typ, tuple):
                        c = _PLY_TYPES[typ[1]]; it = _PLY_TYPES[typ[2]]
                        (n,) = struct.unpack_from(endian + c, body, pos); pos += struct.calcsize(c)
                        row[name] = list(struct.unpack_from(endian + it * n, body, pos))
                        pos += struct.calcsize(it) * n
                    else:
                        c = _PLY_TYPES[typ]
                        (row[name],) = struct.unpack_from(endian + c, body, pos); pos += struct.calcsize(c)
                rows.append(row)
            ply.elements[el] = rows
    return ply


def write_ply(path, verts, faces, binary=False):
    """verts: list of (x, y, z); faces: list of index triples. binary keeps NaN exact."""
    header = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              % ("binary_little_endian" if binary else "ascii", len(verts)))
    if faces is not None:
        header += "element face %d\nproperty list uchar int vertex_indices\n" % len(faces)
    header += "end_header\n"
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        if binary:
            for v in verts:
                f.write(struct.pack("<fff", *v))
            for t in faces or []:
                f.write(struct.pack("<Biii", 3, *t))
        else:
            for v in verts:
                f.write(("%.9g %.9g %.9g\n" % tuple(v)).encode())
            for t in faces or []:
                f.write(("3 %d %d %d\n" % tuple(t)).encode())



def plate_and_square(folder, n=10):
    """A flat n x n plate of unit cells (plate.ply in `folder`) and a closed snake file made on
    it around the square [2.5, 7.5]^2 (square.json, samples only: the cut traces the curve):
    the square's inside has area 25 exactly. Returns (mesh, curve file, curve dict)."""
    verts = [(i, j, 0) for j in range(n + 1) for i in range(n + 1)]
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            faces += [(a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)]
    mesh = os.path.join(folder, "plate.ply")
    write_ply(mesh, verts, faces)

    def loc(x, y):
        i, j = int(x), int(y)
        fx, fy = x - i, y - j
        if fx >= fy:
            return {"face": 2 * (j * n + i), "bary": [1 - fx, fx - fy, fy], "position": [x, y, 0]}
        return {"face": 2 * (j * n + i) + 1, "bary": [1 - fy, fx, fy - fx], "position": [x, y, 0]}

    curve = {"closed": True, "samples": [loc(2.5, 2.5), loc(7.5, 2.5), loc(7.5, 7.5), loc(2.5, 7.5)]}
    path = os.path.join(folder, "square.json")
    with open(path, "w") as f:
        json.dump(curve, f)
    return mesh, path, curve

def inside_area(ply):
    """Area of the faces a cut marked inside (face quality 1) of a mesh in the plane z = 0, such
    as plate_and_square's plate."""
    area = 0.0
    for f in ply.faces:
        if f["quality"] == 1:
            a, b, c = (ply.vertices[i] for i in f["vertex_indices"])
            area += abs((b["x"] - a["x"]) * (c["y"] - a["y"]) - (c["x"] - a["x"]) * (b["y"] - a["y"])) / 2
    return area


def grid_cube(n):
    """Unit cube [0,1]^3 with an n x n grid of quads (two triangles each) per side,
    outward oriented, vertices shared. Returns (verts, faces)."""
    index = {}
    verts = []
    faces = []

    def vid(p):
        key = tuple(int(round(c * n)) for c in p)
        if key not in index:
            index[key] = len(verts)
            verts.append(tuple(k / n for k in key))
        return index[key]

    for axis in range(3):
        u, w = (axis + 1) % 3, (axis + 2) % 3
        for side in (0, 1):
            for i in range(n):
                for j in range(n):
                    def P(a, b):
                        p = [0.0, 0.0, 0.0]
                        p[axis] = float(side); p[u] = a / n; p[w] = b / n
                        return p
                    q = [vid(P(i, j)), vid(P(i + 1, j)), vid(P(i + 1, j + 1)), vid(P(i, j + 1))]
                    if side == 0:
                        q.reverse()
                    faces.append((q[0], q[1], q[2]))
                    faces.append((q[0], q[2], q[3]))
    return verts, faces


def on_cube_edge(p, eps=1e-6):
    """True if p lies on an edge of the unit cube (two coordinates at 0 or 1)."""
    return sum(1 for c in p if abs(c) < eps or abs(c - 1) < eps) >= 2


def cube_edge_distance(p):
    """Distance of a point on the unit cube's surface to the nearest cube edge."""
    ds = []
    for a in range(3):
        for b in range(a + 1, 3):
            da = min(abs(p[a]), abs(p[a] - 1)); db = min(abs(p[b]), abs(p[b] - 1))
            ds.append(math.hypot(da, db))
    return min(ds)


def pick_feature_seeds(path, k=3, threshold=0.1):
    """k feature vertices (energy < threshold) of a saved PLY, far apart (farthest-point
    sampling from the lowest-energy vertex). Returns 0-based vertex indices, in file order."""
    vs = read_ply(path).vertices
    feats = [i for i, v in enumerate(vs) if v["quality"] < threshold] or list(range(len(vs)))
    pos = {i: (vs[i]["x"], vs[i]["y"], vs[i]["z"]) for i in feats}
    seeds = [min(feats, key=lambda i: vs[i]["quality"])]
    dist = {i: math.dist(pos[i], pos[seeds[0]]) for i in feats}
    while len(seeds) < k:
        nxt = max(feats, key=lambda i: dist[i])
        seeds.append(nxt)
        for i in feats:
            dist[i] = min(dist[i], math.dist(pos[i], pos[nxt]))
    return seeds


# ---------------------------------------------------------------------------- CLI
def cube_edge_seeds(path, offset):
    """For a rotated icosphere projected onto [-1,1]^3 (data/icocube.ply): the vertices nearest to
    4 points `offset` mean edge lengths off the cube edge x = y = 1 on the face x = 1, and the mean
    edge length h. Returns (seeds, h)."""
    ply = read_ply(path)
    pts = [(v["x"], v["y"], v["z"]) for v in ply.vertices]
    lengths = []
    for f in ply.faces:
        idx = next(iter(f.values()))  # the vertex index list, whatever its name
        for i in range(3):
            lengths.append(math.dist(pts[idx[i]], pts[idx[(i + 1) % 3]]))
    h = sum(lengths) / len(lengths)
    seeds = []
    for z in (-0.6, -0.2, 0.2, 0.6):
        target = (1.0, 1.0 - offset * h, z)
        seeds.append(min(range(len(pts)), key=lambda i: math.dist(pts[i], target)))
    return seeds, h


def cylinder_cap_seeds(path, radius, count=6):
    """For the rotated icosphere projected onto the capped cylinder x^2 + y^2 <= 1, |z| <= 1
    (data/icocylinder.ply): the vertices nearest to `count` points on the circle of `radius` on
    the top cap z = 1, and the mean edge length h. Returns (seeds, h)."""
    ply = read_ply(path)
    pts = [(v["x"], v["y"], v["z"]) for v in ply.vertices]
    lengths = []
    for f in ply.faces:
        idx = next(iter(f.values()))
        for i in range(3):
            lengths.append(math.dist(pts[idx[i]], pts[idx[(i + 1) % 3]]))
    h = sum(lengths) / len(lengths)
    seeds = []
    for k in range(count):
        a = 2 * math.pi * k / count
        target = (radius * math.cos(a), radius * math.sin(a), 1.0)
        seeds.append(min(range(len(pts)), key=lambda i: math.dist(pts[i], target)))
    return seeds, h


def cylinder_rim_distance(p):
    """Distance from p to the top rim (radius 1, z = 1) of the capped cylinder."""
    return math.hypot(math.hypot(p[0], p[1]) - 1.0, p[2] - 1.0)


def summary(path):
    ply = read_ply(path)
    vs = ply.vertices
    lines = ["%s: %d vertices, %d faces" % (path, len(vs), len(ply.faces))]
    if vs and "quality" in vs[0]:
        q = [v["quality"] for v in vs]
        lines.append("  vertex quality (feature energy): min %.4f  max %.4f  mean %.4f" % (min(q), max(q), sum(q) / len(q)))
        lines.append("  vertices with energy < 0.25 (features): %d" % sum(1 for x in q if x < 0.25))
    if vs and "flags" in vs[0]:
        lines.append("  selected vertices (seed path): %d" % sum(1 for v in vs if v["flags"] & SELECTED))
    return "\n".join(lines)


def _cli_value(text):
    if text in ("true", "false"):
        return text == "true"
    for conv in (int, float):
        try:
            return conv(text)
        except ValueError:
            pass
    return text


def _cli_mlx(out, args):
    filters, cur = [], None
    for a in args:
        if a == "--":
            cur = None
        elif cur is None:
            cur = (a, {})
            filters.append(cur)
        else:
            k, _, v = a.partition("=")
            cur[1][k] = _cli_value(v)
    write_mlx(out, filters)


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "summary":
        for p in sys.argv[2:]:
            print(summary(p))
    elif len(sys.argv) >= 3 and sys.argv[1] == "seeds":
        k = int(sys.argv[3]) if len(sys.argv) > 3 else 3
        print(", ".join(str(i) for i in pick_feature_seeds(sys.argv[2], k)))
    elif len(sys.argv) >= 4 and sys.argv[1] == "mlx":
        _cli_mlx(sys.argv[2], sys.argv[3:])
    else:
        print(__doc__)
        sys.exit(2)


class WorkDirTestCase(unittest.TestCase):
    """A unittest case with its own work folder per test method, under the folder named by the
    environment variable WORK_ENV (the build tree's, so failures leave their files to look at)."""
    WORK_ENV = "GS_HOST_WORK"
    maxDiff = None

    def setUp(self):
        base = os.environ.get(self.WORK_ENV) or tempfile.gettempdir()
        os.makedirs(base, exist_ok=True)
        self.work = tempfile.mkdtemp(prefix=self._testMethodName + "-", dir=base)

    def path(self, name):
        return os.path.join(self.work, name)

    def run_script(self, mesh, filters, outputs=()):
        """Runs the filters on `mesh` through meshlabserver (its output kept beside the script as
        .mlx.log). outputs: extra meshlabserver args per output, e.g. ["-o", out, "-m", "vq"]."""
        mlx = self.path("script%d.mlx" % len(os.listdir(self.work)))
        write_mlx(mlx, filters)
        args = ["-i", mesh]
        for o in outputs:
            args += list(o)
        args += ["-s", mlx]
        rc, out = run_meshlabserver(args, cwd=self.work)
        with open(mlx + ".log", "w") as f:
            f.write(out)
        self.assertGreaterEqual(rc, 0, "meshlabserver CRASHED (signal %d):\n%s" % (-rc, out))
        return rc, out

    def write_cube(self, n, name="cube.ply"):
        """The grid cube of n x n quads per side as `name` in the work folder; sets self.cube,
        self.cube_verts, self.cube_faces."""
        self.cube_verts, self.cube_faces = grid_cube(n)
        self.cube = self.path(name)
        write_ply(self.cube, self.cube_verts, self.cube_faces)
        return self.cube
