#!/usr/bin/env python3
"""The geometric-snake program: every run ends and says why (issue 33), and a stroke across a
part completes into a loop round it (--complete-loop). No MeshLab needed.

CTest registers every `def test_*` below as `cli_<name>` (label `cli`). The stop reason is in the
--json-log line ("stop", "stop_message", "converged", "warnings") and on stderr.
"""

import json
import math
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "host"))
sys.path.insert(0, HERE)
import mlhost  # noqa: E402
from test_cli import ICO, ico_seeds, run  # noqa: E402

DATA = os.environ.get("GS_DATA_DIR", os.path.join(HERE, "..", "..", "data"))
LION = os.path.join(DATA, "..", "..", "shared", "data", "meshes", "lion-head.off")
LION_EYE = "8111,1644,6377,1581,8187,8109"  # round lion-head's right eye seen from the front


def limb_on_body(path, around=48, radius=1.0, height=4.0, up_y=False):
    """A flat annulus (radii 1 to 3.5, z = 0) with a tube of radius 1 standing on it (z 0 to 4, flat
    cap): the limb's base is the circle of radius 1 in z = 0 (as tests/test_stroke_loop.cpp).
    up_y: turned about x so that the limb stands along +y (MeshLab's default view sees its side)."""
    h = 2 * math.pi * radius / around
    rb, rl = round(2.5 / h), round(height / h)
    V = []
    for j in range(rb + 1):
        r = 3.5 - 2.5 * j / rb
        V += [(r * math.cos(2 * math.pi * (i + 0.5 * (j % 2)) / around),
               r * math.sin(2 * math.pi * (i + 0.5 * (j % 2)) / around), 0.0) for i in range(around)]
    for j in range(1, rl + 1):
        z = height * j / rl
        V += [(radius * math.cos(2 * math.pi * (i + 0.5 * ((rb + j) % 2)) / around),
               radius * math.sin(2 * math.pi * (i + 0.5 * ((rb + j) % 2)) / around), z) for i in range(around)]
    V.append((0.0, 0.0, height))
    rings, tip = rb + rl + 1, len(V) - 1
    F = []
    for j in range(rings - 1):
        for i in range(around):
            a, b = j * around + i, j * around + (i + 1) % around
            c, d = (j + 1) * around + (i + 1) % around, (j + 1) * around + i
            F += [(a, b, d), (b, c, d)] if j % 2 == 0 else [(a, b, c), (a, c, d)]
    F += [((rings - 1) * around + i, (rings - 1) * around + (i + 1) % around, tip) for i in range(around)]

    def orient(f):  # normals: +z on the body and the cap, outwards on the tube
        p = [V[k] for k in f]
        c = [sum(x[i] for x in p) / 3 for i in range(3)]
        u = [p[1][i] - p[0][i] for i in range(3)]
        w = [p[2][i] - p[0][i] for i in range(3)]
        n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        out = (0, 0, 1) if c[2] < 1e-6 or c[2] > height - 1e-6 else (c[0], c[1], 0)
        return f if sum(n[i] * out[i] for i in range(3)) >= 0 else (f[0], f[2], f[1])
    F = [orient(f) for f in F]
    if up_y:
        V = [(x, z, -y) for x, y, z in V]
    with open(path, "w") as o:
        o.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        o.writelines("%.9g %.9g %.9g\n" % v for v in V)
        o.writelines("3 %d %d %d\n" % f for f in F)
    return h


class CliRunEndTests(mlhost.WorkDirTestCase):
    WORK_ENV = "GS_CLI_WORK"

    def snake(self, args):
        rc, out, err = run(["snake"] + args + ["--json-log"])
        self.assertEqual(rc, 0, out + err)
        return json.loads(out.strip().splitlines()[-1]), err

    def test_run_end_converged(self):
        seeds, _ = ico_seeds(2.5)
        j, err = self.snake([ICO, "--seeds", seeds])
        self.assertEqual(j["stop"], "converged")
        self.assertTrue(j["converged"])
        self.assertRegex(err, r"\d+ operations, converged")

    def test_run_end_collapsed_lion_eye(self):
        """The issue's lion-head eye: the loop collapses into the eye socket; the run says so."""
        if not os.path.exists(LION):
            self.skipTest("no lion-head.off")
        j, err = self.snake([LION, "--seeds", LION_EYE, "--closed"])
        self.assertEqual(j["stop"], "collapsed", j)
        self.assertFalse(j["converged"])
        self.assertLessEqual(j["operations"], 50)
        self.assertIn("collapsing", j["stop_message"])
        self.assertEqual(sum("collapsing" in w for w in j["warnings"]), 1, j["warnings"])
        self.assertIn("STOPPED: the closed snake collapses", err)
        self.assertIn("warning: the closed snake is collapsing", err)

    def test_run_end_max_operations_and_time_limit(self):
        seeds, _ = ico_seeds(2.5)
        j, err = self.snake([ICO, "--seeds", seeds, "--max-operations", "2"])
        self.assertEqual((j["stop"], j["operations"], j["converged"]), ("max_operations", 2, False))
        self.assertIn("Max operations (2) reached", j["stop_message"])
        self.assertTrue(any("Max operations (2)" in w for w in j["warnings"]), j["warnings"])
        self.assertIn("NOT converged: Max operations reached", err)
        j, err = self.snake([ICO, "--seeds", seeds, "--time-limit", "1e-6"])
        self.assertEqual((j["stop"], j["operations"]), ("time_limit", 1))
        self.assertAlmostEqual(j["parameters"]["time-limit"], 1e-6, places=9)
        self.assertIn("NOT converged: time limit reached", err)
        rc, out, err = run(["snake", ICO, "--seeds", seeds, "--time-limit", "-1", "--json-log"])
        self.assertEqual(rc, 1, err)
        self.assertIn("--time-limit must be in [0, 1000000], not -1", err)

    def test_complete_loop_round_a_limb(self):
        """--complete-loop: five seed points across the limb's +x side become a closed snake round
        the limb, which settles on its base (the circle of radius 1 in z = 0)."""
        mesh = self.path("limb.off")
        h = limb_on_body(mesh)
        pts = ";".join("%g %g 0.6" % (math.cos(math.radians(a)), math.sin(math.radians(a))) for a in range(-80, 81, 40))
        out = self.path("loop.json")
        j, err = self.snake([mesh, "--seed-points", pts, "--complete-loop", "-o", out])
        self.assertTrue(j["closed"])
        with open(out) as f:
            s = json.load(f)
        init = [p["position"] for p in s["initial"]["samples"]]
        # the initial loop goes round the limb: its samples cover every direction round the axis
        sectors = {int((math.degrees(math.atan2(p[1], p[0])) + 180) // 45) for p in init}
        self.assertEqual(len(sectors), 8, sectors)
        self.assertEqual(j["stop"], "converged", j)
        d = max(math.hypot(math.hypot(p["position"][0], p["position"][1]) - 1, p["position"][2]) for p in s["samples"])
        self.assertLess(d, h, "every sample within one edge length of the limb's base")
        rc, _, err = run(["snake", mesh, "--seed-points", pts, "--complete-loop", "--closed", "--json-log"])
        self.assertEqual(rc, 1, err)
        self.assertIn("leave Closed off", err)


if __name__ == "__main__":
    unittest.main()
