#!/usr/bin/env python3
"""The geometric-snake program and the installed MeshLab filters (meshlabserver) give the same
results: the same curve to 1e-9 on the icocube edge, fandisk's crease and a closed cylinder
rim, and the same feature energy. Each tool is run with its defaults where the other has the
same default (the shared parameter definition), and meshlabserver with every parameter named.

CTest: `cli_host_<name>` (label `host`, after host_plugin_installed).
Environment: GS_CLI, GS_DATA_DIR, GS_CLI_WORK.
"""

import json
import math
import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "host"))
import mlhost  # noqa: E402
from mlhost import FILTER_ENERGY, FILTER_SNAKE  # noqa: E402

CLI = os.environ.get("GS_CLI", "geometric-snake")
DATA = os.environ.get("GS_DATA_DIR", os.path.join(HERE, "..", "..", "data"))
TOL = 1e-9


def mean_edge(path):
    ply = mlhost.read_ply(path)
    pts = [(v["x"], v["y"], v["z"]) for v in ply.vertices]
    lengths = []
    for f in ply.faces:
        idx = next(iter(f.values()))
        lengths += [math.dist(pts[idx[i]], pts[idx[(i + 1) % 3]]) for i in range(3)]
    return pts, sum(lengths) / len(lengths)


def nearest(pts, target):
    return min(range(len(pts)), key=lambda i: math.dist(pts[i], target))


class CliHostTests(mlhost.WorkDirTestCase):
    WORK_ENV = "GS_CLI_WORK"

    def filter_snake(self, mesh, seeds, closed, out, **extra):
        mlx = self.path("snake.mlx")
        params = {"Seeds": seeds, "Closed": closed, "Alpha": 0.05, "Beta": 0.5, "Gamma": 1.0, "ExternalWeight": 1.0,
                  "Spacing": 1.0, "MaxOperations": 500, "Method": 0, "UseQuality": False, "OutputFile": out,
                  "NewLayer": False}
        params.update(extra)
        mlhost.write_mlx(mlx, [(FILTER_SNAKE, params)])  # write_mlx adds the newer parameters' defaults
        rc, log = mlhost.run_meshlabserver(["-i", mesh, "-s", mlx], cwd=self.work)
        self.assertEqual(rc, 0, log)
        self.assertNotIn("Geometric snake error", log)
        return json.load(open(out))

    def cli(self, args):
        p = subprocess.run([CLI] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                           timeout=300)
        self.assertEqual(p.returncode, 0, p.stderr.decode())
        return p.stdout.decode()

    def assert_same_curve(self, mesh, seeds, closed):
        ml = self.filter_snake(mesh, seeds, closed, self.path("filter.json"))
        args = ["snake", mesh, "--seeds", seeds, "-o", self.path("cli.json"), "-q"]
        if closed:
            args.append("--closed")
        self.cli(args)
        return self.assert_same(ml, json.load(open(self.path("cli.json"))), os.path.basename(mesh))

    def assert_same(self, ml, cl, what):
        self.assertEqual(ml["params"], cl["params"])
        self.assertEqual(ml["closed"], cl["closed"])
        self.assertEqual(ml["stats"]["operations"], cl["stats"]["operations"])
        self.assertEqual(ml["stats"]["converged"], cl["stats"]["converged"])
        self.assertEqual([s["face"] for s in ml["samples"]], [s["face"] for s in cl["samples"]])
        worst = 0.0
        for key in ("polyline",):
            self.assertEqual(len(ml[key]), len(cl[key]))
            for a, b in zip(ml[key], cl[key]):
                worst = max(worst, max(abs(x - y) for x, y in zip(a, b)))
        for a, b in zip(ml["samples"], cl["samples"]):
            worst = max(worst, max(abs(x - y) for x, y in zip(a["position"], b["position"])))
            worst = max(worst, max(abs(x - y) for x, y in zip(a["bary"], b["bary"])))
        print("%s: %d samples, %d curve points, %d operations, largest difference %.3g"
              % (what, len(cl["samples"]), len(cl["polyline"]), cl["stats"]["operations"], worst))
        self.assertLessEqual(worst, TOL)
        return cl

    def test_same_curve_icocube_edge(self):
        seeds, h = mlhost.cube_edge_seeds(os.path.join(DATA, "icocube.ply"), 2.5)
        j = self.assert_same_curve(os.path.join(DATA, "icocube.ply"), ",".join(map(str, seeds)), False)
        self.assertTrue(j["stats"]["converged"])

    def test_same_curve_fandisk(self):
        # The demo's open snake beside fandisk's curved crease (scripts/demo_headless.sh).
        self.assert_same_curve(os.path.join(DATA, "fandisk.ply"), "1493, 1486, 1644, 2151", False)

    def test_same_curve_closed_rim(self):
        """A closed snake started 2 edge lengths below the top rim of the capped cylinder."""
        mesh = os.path.join(DATA, "icocylinder.ply")
        pts, h = mean_edge(mesh)
        seeds = [nearest(pts, (math.cos(a), math.sin(a), 1.0 - 2.0 * h))
                 for a in (0.0, math.pi / 2, math.pi, 1.5 * math.pi)]
        j = self.assert_same_curve(mesh, ",".join(map(str, seeds)), True)
        self.assertTrue(j["closed"])

    def test_same_curve_seed_points(self):
        """Seeds as 3D points (SeedPoints / --seed-points), snapped onto the surface, beside the icocube edge."""
        mesh = os.path.join(DATA, "icocube.ply")
        _, h = mean_edge(mesh)
        text = "; ".join("%r %r %r" % (1.0, 1.0 - 2.0 * h, z) for z in (-0.6, -0.2, 0.2, 0.6))
        ml = self.filter_snake(mesh, "", False, self.path("filter.json"), SeedPoints=text)
        self.cli(["snake", mesh, "--seed-points", text, "-o", self.path("cli.json"), "-q"])
        self.assert_same(ml, json.load(open(self.path("cli.json"))), "icocube.ply (seed points)")

    def test_same_energy(self):
        mesh = os.path.join(DATA, "fandisk.ply")
        for etype, key in ((0, "normal"), (1, "curvature"), (2, "quadric")):
            with self.subTest(type=key):
                mlx = self.path("e.mlx")
                mlhost.write_mlx(mlx, [(FILTER_ENERGY, {"EnergyType": etype, "SmoothingSteps": 2, "Colorize": True})])
                rc, log = mlhost.run_meshlabserver(["-i", mesh, "-o", self.path("ml.ply"), "-m", "vq", "vc", "-s", mlx],
                                                   cwd=self.work)
                self.assertEqual(rc, 0, log)
                self.cli(["energy", mesh, "--type", key, "-o", self.path("cli.ply"), "-q"])
                a, b = mlhost.read_ply(self.path("ml.ply")).vertices, mlhost.read_ply(self.path("cli.ply")).vertices
                self.assertEqual(len(a), len(b))
                self.assertEqual(max(abs(x["quality"] - y["quality"]) for x, y in zip(a, b)), 0.0)
                self.assertEqual([(x["red"], x["green"], x["blue"]) for x in a],
                                 [(y["red"], y["green"], y["blue"]) for y in b])


if __name__ == "__main__":
    unittest.main()
