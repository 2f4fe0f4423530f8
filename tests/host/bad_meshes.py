#!/usr/bin/env python3
"""The project's bad-input corpus: meshes users bring that a filter must survive.

    python3 bad_meshes.py OUTDIR      # writes OUTDIR/<name>.ply for every case, lists them

Each case is a small mesh (binary PLY, so NaN and Inf coordinates are exact) with the seeds a
test should try on it (vertex indices, in file order). test_bad_meshes.py runs every filter of
the plugin on each and asserts a success with finite output or a clear error, never a crash,
a hang or a NaN. No third-party modules.
"""

import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mlhost  # noqa: E402


def grid(nu, nv, f):
    """Parametric (u, v) in [0,1]^2 grid, nu x nv quads, two triangles each; f(u, v) -> xyz."""
    verts = [f(i / nu, j / nv) for j in range(nv + 1) for i in range(nu + 1)]
    faces = []
    for j in range(nv):
        for i in range(nu):
            a = j * (nu + 1) + i
            b, c, d = a + 1, a + nu + 2, a + nu + 1
            faces += [(a, b, c), (a, c, d)]
    return verts, faces


def cube(n=6, scale=1.0):
    v, f = mlhost.grid_cube(n)
    return [tuple(c * scale for c in p) for p in v], f


def cube_seeds(verts, closed=False):
    """Vertices at three cube corners (an open path along two edges, or a closed loop)."""
    def nearest(q):
        return min(range(len(verts)), key=lambda i: sum((a - b) ** 2 for a, b in zip(verts[i], q)))
    s = max(max(abs(c) for c in p) for p in verts if all(math.isfinite(c) for c in p))
    return [nearest((0, 0, 0)), nearest((s, 0, 0)), nearest((s, s, 0))]


def spread_seeds(nverts, k=3):
    """k vertex indices spread over the file order."""
    if nverts == 0:
        return [0, 1, 2][:k]
    return [min(nverts - 1, (i * nverts) // k + (nverts // (2 * k))) for i in range(k)]


def cases():
    """name -> (verts, faces or None, seeds, what it is)."""
    rnd = random.Random(8)
    out = {}

    out["empty"] = ([], [], [0, 1, 2], "no vertices, no faces")

    pc = [(rnd.random(), rnd.random(), rnd.random()) for _ in range(60)]
    out["point_cloud"] = (pc, None, [0, 20, 40], "60 points, no face element")

    # Two fans meeting in one vertex: a non-manifold (bowtie) vertex.
    v = [(0, 0, 0)]
    f = []
    for side in (1, -1):
        base = len(v)
        for k in range(5):
            a = math.pi * (0.2 + 0.15 * k)
            v.append((side * math.cos(a), math.sin(a) * 0.5, side * math.sin(a)))
        for k in range(4):
            f.append((0, base + k, base + k + 1) if side > 0 else (0, base + k + 1, base + k))
    out["bowtie"] = (v, f, [1, 0, 8], "two triangle fans sharing only one vertex")

    v, f = grid(6, 6, lambda u, w: (u, w, 0.0))
    top = len(v)
    v.append((0.5, 0.5, 0.6))
    # three extra faces on interior edges: edges shared by three and four faces.
    f += [(8, 9, top), (9, 16, top), (15, 16, top)]
    out["nonmanifold_edge"] = (v, f, [0, 24, 48], "a flat grid with fins on interior edges")

    v, f = grid(6, 6, lambda u, w: (u, w, 0.1 * math.sin(3 * u)))
    n = len(v)
    v += [(0.2, 0.2, 0.0), (0.4, 0.4, 0.0), (0.6, 0.6, 0.0)]
    f.append((n, n + 1, n + 2))  # collinear: zero area
    v[10] = v[11]                # two coincident vertices: the faces between them collapse
    out["zero_area_faces"] = (v, f, [0, 24, 48], "collinear and collapsed triangles among good ones")

    v, f = cube(4)
    f = f + [(3, 3, 7)]
    out["repeated_vertex_face"] = (v, f, cube_seeds(v), "a cube plus a face that names one vertex twice")

    v, f = cube()
    v[len(v) // 2] = (float("nan"), 0.5, 0.5)
    out["nan_coords"] = (v, f, cube_seeds(v), "a cube with one NaN vertex")

    v, f = cube()
    v[len(v) // 3] = (0.5, float("inf"), 0.5)
    v[len(v) // 2] = (0.5, 0.5, float("-inf"))
    out["inf_coords"] = (v, f, cube_seeds(v), "a cube with +Inf and -Inf vertices")

    cv, cf = cube(4)
    v, f = [], []
    for t in cf:
        f.append((len(v), len(v) + 1, len(v) + 2))
        v += [cv[i] for i in t]
    out["triangle_soup"] = (v, f, [0, len(v) // 2, len(v) - 1], "a cube with no shared vertices (STL-like)")

    def mobius(u, w):
        a = 2 * math.pi * u
        r = 1 + (w - 0.5) * 0.6 * math.cos(a / 2)
        return (r * math.cos(a), r * math.sin(a), (w - 0.5) * 0.6 * math.sin(a / 2))
    v, f = grid(24, 3, mobius)
    # glue the ends with the half twist: u=1 row j meets u=0 row (3-j)
    nu = 24
    idx = {}
    for j in range(4):
        idx[j * (nu + 1) + nu] = (3 - j) * (nu + 1)
    f = [tuple(idx.get(i, i) for i in t) for t in f]
    out["mobius"] = (v, f, [0, 12, 50], "a Moebius strip: non-orientable")

    v, f = cube()
    f = [(t[0], t[2], t[1]) if k % 3 == 0 else t for k, t in enumerate(f)]
    out["flipped_faces"] = (v, f, cube_seeds(v), "a cube with a third of its faces reversed")

    v, f = [], []
    for k in range(150):
        c = (rnd.uniform(0, 10), rnd.uniform(0, 10), rnd.uniform(0, 10))
        b = len(v)
        v += [c, (c[0] + .3, c[1], c[2]), (c[0], c[1] + .3, c[2]), (c[0], c[1], c[2] + .3)]
        f += [(b, b + 2, b + 1), (b, b + 1, b + 3), (b, b + 3, b + 2), (b + 1, b + 2, b + 3)]
    out["many_components"] = (v, f, [0, 1, 2, 4], "150 separate tetrahedra; seeds on two of them")

    v, f = cube(8)
    rnd2 = random.Random(3)
    drop = set(rnd2.sample(range(len(f)), len(f) // 6))
    f = [t for k, t in enumerate(f) if k not in drop]
    out["holes"] = (v, f, cube_seeds(v), "a cube with a sixth of its faces missing")

    for name, s in (("scale_1e-30", 1e-30), ("scale_1e30", 1e30)):
        v, f = cube(6, s)
        out[name] = (v, f, cube_seeds(v), "a unit cube scaled by %g" % s)

    v, f = grid(40, 2, lambda u, w: (u * 100.0, w * 0.01, 0.02 * math.sin(10 * u)))
    out["slivers"] = (v, f, [0, 40, 122], "a 100 x 0.01 strip of needle triangles (aspect 1000)")

    v, f = cube(4)
    f = f + f[:10]
    out["duplicate_faces"] = (v, f, cube_seeds(v), "a cube with ten faces twice")

    out["single_triangle"] = ([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)], [0, 1, 2], "one triangle")

    v, f = cube(4)
    v += [(5, 5, 5)] * 3
    out["unreferenced_vertices"] = (v, f, [len(v) - 1, 0, 5], "a cube plus isolated vertices, seed on one")

    v, f = cube(4)
    v = [(x + 1e7, y + 1e7, z + 1e7) for x, y, z in v]
    out["far_from_origin"] = (v, f, cube_seeds([(x - 1e7, y - 1e7, z - 1e7) for x, y, z in v]),
                              "a unit cube at 1e7: its vertices merge in float")

    # a 33-degree V-ridge on a 300 x 300 grid: one line of vertices, 0.3 % of the mesh
    t = math.tan(math.radians(16.5))
    v, f = grid(300, 300, lambda u, w: (u, w, t * (0.5 - abs(u - 0.5))))
    out["thin_ridge_300"] = (v, f, [150, 150 + 301 * 150, 150 + 301 * 300], "a 33-degree ridge on a 300 x 300 grid")
    return out


TET_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
PLY_HEAD = ("ply\nformat ascii 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\n"
            "element face %s\nproperty list uchar int vertex_indices\nend_header\n")

# Files MeshLab 2020.09's own importers (vcglib) abort on while opening them, before any plugin
# runs: the host test records it, the program must refuse them cleanly (issue 36).
HOST_IMPORTER_ABORTS = {"obj_vertex_one", "obj_cube", "obj_far_index", "ply_negative_count", "ply_count_past_int64",
                        "off_negative_counts"}


def raw_cases():
    """name -> (extension, file text, seeds, what it is): files as hostile users write them (issue 36)."""
    cube_v, cube_f = cube(4)
    cube_obj = "".join("v %r %r %r\n" % p for p in cube_v) + "".join("f %d %d %d\n" % (a + 1, b + 1, c + 1)
                                                                     for a, b, c in cube_f)
    return {
        "obj_vertex_one": ("obj", TET_OBJ + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n", [0, 1, 2],
                           "a tetrahedron OBJ: three faces use vertex 1 (vcglib drops them)"),
        "obj_cube": ("obj", cube_obj, cube_seeds(cube_v), "a cube OBJ (vcglib drops the faces at vertex 1)"),
        "obj_far_index": ("obj", TET_OBJ + "f 1 3 2\nf 1 2 100000\nf 2 3 4\n", [0, 1, 2],
                          "an OBJ face with index 100000 (vcglib read past its vertices)"),
        "ply_negative_count": ("ply", PLY_HEAD % ("-5", "1") + "3 0 1 2\n", [0, 1, 2], "element vertex -5"),
        "ply_count_past_int64": ("ply", PLY_HEAD % ("3", "99999999999999999999999") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                                 [0, 1, 2], "a face count past int64"),
        "ply_truncated": ("ply", PLY_HEAD % ("30", "1") + "0 0 0\n1 0 0\n", [0, 1, 2], "30 vertices announced, 2 given"),
        "off_negative_counts": ("off", "OFF\n-4 -2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", [0, 1, 2],
                                "negative OFF counts"),
    }


def write_all(outdir):
    os.makedirs(outdir, exist_ok=True)
    made = {}
    for name, (v, f, seeds, what) in cases().items():
        path = os.path.join(outdir, name + ".ply")
        mlhost.write_ply(path, v, f, binary=True)
        made[name] = (path, seeds, what)
    for name, (ext, text, seeds, what) in raw_cases().items():
        path = os.path.join(outdir, name + "." + ext)
        with open(path, "w") as f:
            f.write(text)
        made[name] = (path, seeds, what)
    return made


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    for name, (path, seeds, what) in write_all(sys.argv[1]).items():
        print("%-22s %-60s seeds %s" % (name, what, seeds))
