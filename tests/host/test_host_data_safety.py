#!/usr/bin/env python3
"""Host tests of data safety (issue 8) through meshlabserver: a failing or succeeding filter
never truncates or replaces the user's files, a 10,000-sample sidecar restores in the export
filter, and snakes come out the same on a mesh scaled by 1e-30, 1 and 1e30.

CTest registers every `def test_*` below as `host_<name>` (label `host`).
Run one by hand:  python3 tests/host/test_host_data_safety.py -v DataSafetyTests.test_output_is_the_input_mesh
"""

import json
import math
import os
import struct
import sys
import time
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mlhost  # noqa: E402
from mlhost import FILTER_EXPORT, FILTER_SNAKE  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.environ.get("GS_DATA_DIR", os.path.join(HERE, "..", "..", "data"))


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def write_off(path, verts, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(verts), len(faces)))
        for v in verts:
            f.write("%.9g %.9g %.9g\n" % tuple(v))
        for t in faces:
            f.write("3 %d %d %d\n" % tuple(t))


def write_stl(path, verts, faces):
    with open(path, "wb") as f:
        f.write(b"geometric snake test".ljust(80, b" "))
        f.write(struct.pack("<I", len(faces)))
        for t in faces:
            f.write(struct.pack("<3f", 0, 0, 0))
            for i in t:
                f.write(struct.pack("<3f", *verts[i]))
            f.write(struct.pack("<H", 0))


class DataSafetyTests(mlhost.WorkDirTestCase):
    def setUp(self):
        super().setUp()
        self.verts, self.faces = mlhost.grid_cube(8)

    def snake(self, seeds, out="", closed=False, method=0):
        return (FILTER_SNAKE, {"Seeds": seeds, "Closed": closed, "Alpha": 0.05, "Beta": 0.5, "Gamma": 1.0,
                               "ExternalWeight": 1.0, "Spacing": 1.0, "MaxOperations": 200, "Method": method,
                               "UseQuality": False, "OutputFile": out, "NewLayer": False})

    def export(self, out, which=0):
        return (FILTER_EXPORT, {"OutputFile": out, "Which": which, "NewLayer": False})

    def cube_seeds(self):
        # three vertices near the cube edge x = 1, y = 1 (grid cube, 8 quads per side)
        idx = [self.verts.index((1.0, 0.875, z)) for z in (0.25, 0.5, 0.75)]
        return ",".join(map(str, idx))

    def assert_fails_and_keeps(self, mesh, filters, victim, regex):
        before = read_bytes(victim)
        rc, out = self.run_script(mesh, filters)
        self.assertEqual(rc, 255, "the filter should have failed:\n" + out)
        self.assertRegex(out, r"Geometric snake error: .*" + regex)
        self.assertEqual(read_bytes(victim), before, "%s was changed by a failing filter" % victim)
        return out

    # ------------------------------------------------------------------ data loss cases
    def test_output_with_unknown_or_missing_extension(self):
        """OutputFile = an existing file with an unknown or no extension: the file survives byte for byte."""
        mesh = self.path("cube.ply")
        mlhost.write_ply(mesh, self.verts, self.faces)
        for name in ("notes.txt", "README"):
            victim = self.path(name)
            with open(victim, "wb") as f:
                f.write(b"the user's precious notes\n" * 50)
            with self.subTest(filter="snake", file=name):
                out = self.assert_fails_and_keeps(mesh, [self.snake(self.cube_seeds(), victim)], victim,
                                                  "(Unknown curve format|has no extension)")
                self.assertNotIn("operations", out.split("Geometric snake error")[0].split("filter: ")[-1],
                                 "the output file must be refused before the snake runs")
            with self.subTest(filter="export", file=name):
                self.assert_fails_and_keeps(mesh, [self.snake(self.cube_seeds()), self.export(victim)], victim,
                                            "(Unknown curve format|has no extension)")
        # the message names the missing extension, not the lower-cased path
        out = self.assert_fails_and_keeps(mesh, [self.snake(self.cube_seeds(), self.path("README"))],
                                          self.path("README"), "has no extension")
        self.assertNotIn("format \"" + self.path("README").lower(), out)

    def test_output_is_the_input_mesh(self):
        """OutputFile = the input .off/.stl/.ply mesh (the .ply used to be replaced by the curve, 'OK')."""
        for ext, writer in (("off", write_off), ("stl", write_stl), ("ply", mlhost.write_ply)):
            mesh = self.path("part." + ext)
            writer(mesh, self.verts, self.faces)
            with self.subTest(filter="snake", ext=ext):
                self.assert_fails_and_keeps(mesh, [self.snake(self.cube_seeds(), mesh)], mesh,
                                            "(it is the mesh|Unknown curve format)")
            with self.subTest(filter="export", ext=ext):
                self.assert_fails_and_keeps(mesh, [self.snake(self.cube_seeds()), self.export(mesh)], mesh,
                                            "(it is the mesh|Unknown curve format)")
        # same file, other spelling; and the mesh's sidecar
        mesh = self.path("part.ply")
        other = os.path.join(self.work, ".", "..", os.path.basename(self.work), "part.ply")
        self.assert_fails_and_keeps(mesh, [self.snake(self.cube_seeds(), other)], mesh, "it is the mesh")
        side = mesh + ".snakes.json"
        with open(side, "w") as f:
            f.write("{}")
        self.assert_fails_and_keeps(mesh, [self.snake(self.cube_seeds(), side)], side, "sidecar")

    def test_export_which_out_of_range(self):
        mesh = self.path("cube.ply")
        mlhost.write_ply(mesh, self.verts, self.faces)
        rc, out = self.run_script(mesh, [self.snake(self.cube_seeds()), self.export(self.path("c.json"), which=5)])
        self.assertEqual(rc, 255, out)
        self.assertRegex(out, r"Geometric snake error: .*Which")
        self.assertFalse(os.path.exists(self.path("c.json")))

    # ------------------------------------------------------------------ a 10,000-sample sidecar
    def test_export_restores_a_10000_sample_sidecar(self):
        """The export filter restores a sidecar of 10,000 samples (it crashed: partition overflow)."""
        n = 100
        verts = [(i / n, j / n, 0.0) for j in range(n + 1) for i in range(n + 1)]
        faces = []
        for j in range(n):
            for i in range(n):
                a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
                faces += [(a, b, c), (a, c, d)]
        mesh = self.path("plane.ply")
        mlhost.write_ply(mesh, verts, faces)
        samples = []
        for j in range(n):  # one sample per quad, row by row, back and forth
            for k in range(n):
                i = k if j % 2 == 0 else n - 1 - k
                samples.append({"face": 2 * (j * n + i), "bary": [0.5, 0.3, 0.2], "fixed": (j * n + k) % 997 == 0})
        session = {"format": "geometric-snake-session", "version": 1,
                   "mesh": {"vertices": len(verts), "faces": len(faces)},
                   "energy": {"type": 0, "smoothing": 2}, "seed_cost": 0, "selected": 0, "seeds": [],
                   "snakes": [{"closed": False, "samples": samples}]}
        with open(mesh + ".snakes.json", "w") as f:
            json.dump(session, f)
        side_before = read_bytes(mesh + ".snakes.json")
        out_obj = self.path("curve.obj")
        t0 = time.time()
        rc, out = self.run_script(mesh, [self.export(out_obj)])
        secs = time.time() - t0
        self.assertEqual(rc, 0, out)
        self.assertRegex(out, r"Exported 1 geometric snake\(s\) from .*plane.ply.snakes.json")
        self.assertEqual(read_bytes(mesh + ".snakes.json"), side_before)
        with open(out_obj) as f:
            lines = f.read().splitlines()
        vs = [tuple(map(float, l.split()[1:])) for l in lines if l.startswith("v ")]
        self.assertGreaterEqual(len(vs), 10000)
        self.assertEqual(len([l for l in lines if l.startswith("l ")]), 1)
        for p in vs:  # on the plane, inside it
            self.assertTrue(all(math.isfinite(c) for c in p), p)
            self.assertAlmostEqual(p[2], 0.0, places=6)
            self.assertTrue(-1e-6 <= p[0] <= 1 + 1e-6 and -1e-6 <= p[1] <= 1 + 1e-6, p)
        # the samples are where the sidecar put them (the first quad's sample, the last row's)
        self.assertAlmostEqual(vs[0][0], (0.5 * 0 + 0.3 * 1 + 0.2 * 1) / n, places=5)
        print("10,000-sample sidecar exported in %.2f s (meshlabserver, whole run)" % secs)
        self.assertLess(secs, 60)

    # ------------------------------------------------------------------ any scale
    def test_scale_1e30_and_1e_minus_30(self):
        """The same open snake on icocube scaled by 1e-30, 1 and 1e30 (it collapsed or was refused),
        with either method (the projection's closest face flipped on ties before session 8)."""
        ply = mlhost.read_ply(os.path.join(DATA, "icocube.ply"))
        pts = [(v["x"], v["y"], v["z"]) for v in ply.vertices]
        faces = [tuple(next(iter(f.values()))) for f in ply.faces]
        seeds, h = mlhost.cube_edge_seeds(os.path.join(DATA, "icocube.ply"), 2.0)
        for s in (1.0, 1e-30, 1e30):
            mlhost.write_ply(self.path("icocube_%g.ply" % s), [tuple(c * s for c in p) for p in pts], faces, binary=True)
        for method, name in ((0, "embedding"), (1, "projection")):
            curves = {}
            for s in (1.0, 1e-30, 1e30):
                out_json = self.path("snake_%s_%g.json" % (name, s))
                rc, out = self.run_script(self.path("icocube_%g.ply" % s),
                                          [self.snake(",".join(map(str, seeds)), out_json, method=method)])
                self.assertEqual(rc, 0, out)
                self.assertRegex(out, r"converged")
                with open(out_json) as f:
                    j = json.load(f)
                curves[s] = [tuple(c / s for c in x["position"]) for x in j["samples"]]
            ref = curves[1.0]
            spread = max(math.dist(p, ref[0]) for p in ref)
            self.assertGreater(spread, 1.0, "the reference snake collapsed")
            for s in (1e-30, 1e30):
                with self.subTest(method=name, scale=s):
                    self.assertEqual(len(curves[s]), len(ref))
                    # "the same result to 1e-6 relative" (issue 8): sample by sample, relative to the
                    # mesh's size (its bounding-box diagonal, 2 sqrt(3))
                    size = 2 * math.sqrt(3)
                    worst = max(math.dist(a, b) for a, b in zip(curves[s], ref)) / size
                    print("%s, scale %g: largest sample difference %.3g of the mesh's size (h = %.3g of it)"
                          % (name, s, worst, h / size))
                    self.assertLess(worst, 1e-6)

if __name__ == "__main__":
    unittest.main()
