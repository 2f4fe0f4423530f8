#!/usr/bin/env python3
"""Host integration tests: the installed plugin inside the real MeshLab 2020.09 host,
driven through `xvfb-run -a meshlabserver` and .mlx scripts.

CTest registers every `def test_*` below as its own test `host_<name>` (label `host`),
after `host_plugin_installed` has checked that the installed .so is the freshly built one.
Run one by hand:  python3 tests/host/test_host.py -v HostTests.test_energy_cube

Environment: GS_DATA_DIR (repo data/), GS_HOST_WORK (scratch folder).
"""

import math
import os
import re
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mlhost  # noqa: E402
from mlhost import FILTER_CUT, FILTER_ENERGY, FILTER_EXPORT, FILTER_SEED_PATH, FILTER_SNAKE, SELECTED  # noqa: E402
import json  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.environ.get("GS_DATA_DIR", os.path.join(HERE, "..", "..", "data"))
N = 8  # grid cube resolution: 8x8 quads per side


class HostTests(mlhost.WorkDirTestCase):
    def setUp(self):
        super().setUp()
        self.write_cube(N)

    # ------------------------------------------------------------------ helpers
    def run_script(self, mesh, filters, outputs=(), expect_ok=True):
        """mlhost.WorkDirTestCase.run_script, and with expect_ok: every filter ran and none failed."""
        rc, out = super().run_script(mesh, filters, outputs)
        for name, _ in filters:
            # A filter whose plugin did not load is reported as "filter ... not found".
            self.assertNotIn("filter %s not found" % name, out, out)
        if expect_ok:
            self.assertEqual(rc, 0, "meshlabserver failed:\n" + out)
            self.assertNotIn("Geometric snake error", out, out)
            for name, _ in filters:
                self.assertIn("filter: %s" % name, out, out)
        return rc, out

    def assert_filter_error(self, mesh, filters, message_regex):
        rc, out = self.run_script(mesh, filters, outputs=[["-o", self.path("never.ply")]], expect_ok=False)
        self.assertNotEqual(rc, 0, "the filter should have failed:\n" + out)
        self.assertEqual(rc, 255, "meshlabserver should exit(-1) on a filter error, got %d:\n%s" % (rc, out))
        self.assertRegex(out, r"Geometric snake error: .*" + message_regex)
        self.assertIn("Problem with filter", out)
        self.assertFalse(os.path.exists(self.path("never.ply")), "a failed script must not save a mesh")
        return out

    def energy_params(self, energy_type=0, steps=0, colorize=True):
        return {"EnergyType": energy_type, "SmoothingSteps": steps, "Colorize": colorize}

    def seed_params(self, seeds, closed=False, cost=0, new_layer=True, **kw):
        # Always every parameter: Debian's meshlabserver 2020.09 aborts (an assert in
        # MeshLabServer::script) when a script omits some of a filter's parameters
        # (mlhost.write_mlx adds the newer ones with their defaults).
        p = {"Seeds": seeds, "Closed": closed, "Cost": cost, "NewLayer": new_layer}
        p.update(kw)
        return p

    def cube_index(self, p):
        key = tuple(float(c) for c in p)
        return self.cube_verts.index(key)

    # ------------------------------------------------------------------ tests
    def test_filters_listed(self):
        dump = self.path("filters.txt")
        rc, out = mlhost.run_meshlabserver(["-d", dump], cwd=self.work)
        self.assertEqual(rc, 0, out)
        with open(dump, encoding="utf-8", errors="replace") as f:
            text = f.read()
        for name in (FILTER_ENERGY, FILTER_SEED_PATH, FILTER_SNAKE, FILTER_EXPORT, FILTER_CUT):
            self.assertIn("\\section", text)
            self.assertRegex(text, r"\\section f\d+ " + re.escape(name), "filter %r not loaded by MeshLab" % name)
        for label in ("Energy type", "Smoothing steps", "Colorize by energy", "Seed vertices", "Closed path",
                      "Path cost", "Add path as new layer", "Alpha (tension)", "Max operations", "Use vertex quality",
                      "Output file", "Which snakes"):
            self.assertIn(label, text)

    def test_energy_cube(self):
        """All three energies: quality in [0,1], low on the cube's edges, high on flat sides."""
        for etype in (0, 1, 2):
            with self.subTest(energy_type=etype):
                out_ply = self.path("energy%d.ply" % etype)
                rc, out = self.run_script(self.cube, [(FILTER_ENERGY, self.energy_params(etype, 0, True))],
                                          outputs=[["-o", out_ply, "-m", "vq", "vc", "sa"]])
                self.assertRegex(out, r"Feature energy \(.*\) on %d vertices: raw range \[" % len(self.cube_verts))
                self.assertRegex(out, r"computed in [0-9.]+ ms")
                ply = mlhost.read_ply(out_ply)
                self.assertEqual(len(ply.vertices), len(self.cube_verts))
                q = [v["quality"] for v in ply.vertices]
                for x in q:
                    self.assertTrue(math.isfinite(x) and -1e-6 <= x <= 1 + 1e-6, x)
                self.assertLess(min(q), 0.05)
                self.assertGreater(max(q), 0.95)
                pts = [(v["x"], v["y"], v["z"]) for v in ply.vertices]
                edge = [qq for p, qq in zip(pts, q) if mlhost.on_cube_edge(p)]
                flat = [qq for p, qq in zip(pts, q) if mlhost.cube_edge_distance(p) > 1.5 / N]
                self.assertTrue(edge and flat)
                self.assertLess(sum(edge) / len(edge), 0.5, "cube edges should be features (low energy)")
                self.assertGreater(min(flat), 0.9, "flat sides should have energy ~1")
                self.assertLess(max(edge), min(flat) - 0.3)
                # Colour ramp: red = feature (low), blue = flat (high).
                for p, v in zip(pts, ply.vertices):
                    if v["quality"] < 0.1:
                        self.assertGreater(v["red"], v["blue"], v)
                    if v["quality"] > 0.9:
                        self.assertGreater(v["blue"], v["red"], v)

    def test_energy_smoothing_reports_progress(self):
        """Long smoothing reports through the host's callback (meshlabserver prints it) and ends
        with a valid energy (10000 rounds flatten this small cube's: all in [0, 1])."""
        out_ply = self.path("energy_smooth.ply")
        rc, out = self.run_script(self.cube, [(FILTER_ENERGY, self.energy_params(0, 10000, False))],
                                  outputs=[["-o", out_ply, "-m", "vq"]])
        self.assertEqual(rc, 0, out)
        self.assertIn("Smoothing the feature energy...", out)
        self.assertRegex(out, r"Feature energy \(normal variation, 10000 smoothing steps\)")
        q = [v["quality"] for v in mlhost.read_ply(out_ply).vertices]
        self.assertEqual(len(q), len(self.cube_verts))
        self.assertTrue(all(math.isfinite(x) and -1e-6 <= x <= 1 + 1e-6 for x in q))

    def test_energy_no_colorize_keeps_colours(self):
        out_ply = self.path("q.ply")
        self.run_script(self.cube, [(FILTER_ENERGY, self.energy_params(0, 3, False))],
                        outputs=[["-o", out_ply, "-m", "vq", "vc", "sa"]])
        ply = mlhost.read_ply(out_ply)
        q = [v["quality"] for v in ply.vertices]
        self.assertLess(min(q), 0.05)
        self.assertGreater(max(q), 0.95)
        # meshlabserver writes the (default white) colour when asked to (-m vc); Colorize=false
        # must leave it untouched.
        for v in ply.vertices:
            self.assertEqual((v["red"], v["green"], v["blue"]), (255, 255, 255), v)

    def test_energy_data_meshes(self):
        meshes = [m for m in ("fandisk.ply", "icocube.ply", "icocylinder.ply") if os.path.exists(os.path.join(DATA, m))]
        if not meshes:
            self.skipTest("no data meshes in %s yet" % DATA)
        for m in meshes:
            with self.subTest(mesh=m):
                out_ply = self.path("energy_" + m)
                self.run_script(os.path.join(DATA, m), [(FILTER_ENERGY, self.energy_params(0, 2, True))],
                                outputs=[["-o", out_ply, "-m", "vq", "vc", "sa"]])
                q = [v["quality"] for v in mlhost.read_ply(out_ply).vertices]
                self.assertTrue(all(math.isfinite(x) and -1e-6 <= x <= 1 + 1e-6 for x in q))
                self.assertLess(min(q), 0.05)
                self.assertGreater(max(q), 0.95)
                # Most of a CAD-like model is smooth: the median vertex is not a feature.
                self.assertGreater(sorted(q)[len(q) // 2], 0.5)

    def test_seed_path_along_cube_edge(self):
        a = self.cube_index((0.0, 0.0, 0.0))
        b = self.cube_index((1.0, 0.0, 0.0))
        out_ply, layer_ply = self.path("sel.ply"), self.path("layer.ply")
        rc, out = self.run_script(
            self.cube, [(FILTER_SEED_PATH, {"Seeds": "%d, %d" % (a, b), "Closed": False, "Cost": 0, "NewLayer": True})],
            outputs=[["-o", out_ply, "-m", "vf", "sa"], ["-o", layer_ply, "-l", "x", "-m", "sa"]])
        m = re.search(r"Seed path \(open, length cost\) through 2 seeds: (\d+) vertices selected, length ([0-9.e+-]+)", out)
        self.assertTrue(m, out)
        self.assertEqual(int(m.group(1)), N + 1)
        self.assertAlmostEqual(float(m.group(2)), 1.0, places=4)
        self.assertIn('Added layer "Seed path": %d vertices, %d edges.' % (N + 1, N), out)
        # Selection saved in the vertex flags: exactly the cube edge y = z = 0.
        ply = mlhost.read_ply(out_ply)
        sel = [(v["x"], v["y"], v["z"]) for v in ply.vertices if v["flags"] & SELECTED]
        self.assertEqual(len(sel), N + 1)
        for p in sel:
            self.assertAlmostEqual(p[1], 0.0, places=5)
            self.assertAlmostEqual(p[2], 0.0, places=5)
        # The new layer (saved with -l x, the last layer) holds the path's vertices, in order.
        layer = mlhost.read_ply(layer_ply)
        self.assertEqual(len(layer.vertices), N + 1)
        xs = [v["x"] for v in layer.vertices]
        self.assertEqual(xs, sorted(xs))
        self.assertAlmostEqual(xs[0], 0.0, places=5)
        self.assertAlmostEqual(xs[-1], 1.0, places=5)

    def test_seed_path_closed_feature_cost(self):
        """Three corners of the bottom face, closed, feature cost on a mesh without quality:
        the energy is computed first (said in the Log) and the loop follows the cube's edges."""
        seeds = [self.cube_index(p) for p in ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0))]
        out_ply = self.path("loop.ply")
        rc, out = self.run_script(
            self.cube, [(FILTER_SEED_PATH, {"Seeds": ",".join(map(str, seeds)), "Closed": True, "Cost": 1,
                                            "NewLayer": False})],
            outputs=[["-o", out_ply, "-m", "vf", "vq", "sa"]])
        self.assertIn("had no vertex quality", out)
        self.assertNotIn("Added layer", out)
        m = re.search(r"Seed path \(closed, feature cost\) through 3 seeds: (\d+) vertices selected, length ([0-9.e+-]+)", out)
        self.assertTrue(m, out)
        length = float(m.group(2))
        # Pure shortest loop: 1 + 1 + sqrt(2) (diagonal across the bottom side). Following the
        # cube's edges instead (what the feature cost is for): 1 + 1 + 2 = 4.
        self.assertAlmostEqual(length, 4.0, places=3)
        ply = mlhost.read_ply(out_ply)
        sel = [(v["x"], v["y"], v["z"]) for v in ply.vertices if v["flags"] & SELECTED]
        self.assertEqual(len(sel), int(m.group(1)))
        on_edges = sum(1 for p in sel if mlhost.on_cube_edge(p))
        self.assertGreaterEqual(on_edges / len(sel), 0.9, "feature-cost path should follow cube edges")

    def test_energy_then_seed_path_pipeline(self):
        seeds = [self.cube_index(p) for p in ((0.0, 0.0, 0.0), (1.0, 1.0, 0.0))]
        out_ply = self.path("pipe.ply")
        rc, out = self.run_script(
            self.cube, [(FILTER_ENERGY, self.energy_params(0, 1, True)),
                        (FILTER_SEED_PATH, {"Seeds": "%d,%d" % tuple(seeds), "Closed": False, "Cost": 1,
                                            "NewLayer": True})],
            outputs=[["-o", out_ply, "-m", "vf", "vq", "vc", "sa"]])
        self.assertNotIn("had no vertex quality", out)
        ply = mlhost.read_ply(out_ply)
        self.assertIn("quality", ply.vertices[0])
        self.assertIn("red", ply.vertices[0])
        self.assertGreater(sum(1 for v in ply.vertices if v["flags"] & SELECTED), 2)

    # ------------------------------------------------------------------ errors
    def test_error_bad_seeds(self):
        for seeds, msg in (("0, x", ""), ("", ""), ("5", ""), ("0, 99999", "")):
            with self.subTest(seeds=seeds):
                self.assert_filter_error(self.cube, [(FILTER_SEED_PATH, {"Seeds": seeds, "Closed": False, "Cost": 0,
                                                                         "NewLayer": True})], msg)

    def test_error_bad_smoothing_steps(self):
        for steps in (-1, 10001, 2000000000):
            with self.subTest(steps=steps):
                self.assert_filter_error(self.cube, [(FILTER_ENERGY, self.energy_params(0, steps))], "SmoothingSteps")

    def test_error_point_cloud(self):
        pc = self.path("pc.ply")
        mlhost.write_ply(pc, self.cube_verts, None)
        self.assert_filter_error(pc, [(FILTER_ENERGY, self.energy_params())], "point cloud")
        self.assert_filter_error(pc, [(FILTER_SEED_PATH, self.seed_params("0,1"))], "point cloud")

    def test_error_empty_mesh(self):
        empty = self.path("empty.ply")
        mlhost.write_ply(empty, [], [])
        self.assert_filter_error(empty, [(FILTER_ENERGY, self.energy_params())], "empty")

    def test_error_nan_coordinates(self):
        verts = list(self.cube_verts)
        verts[3] = (float("nan"), 0.5, 0.5)
        bad = self.path("nan.ply")
        mlhost.write_ply(bad, verts, self.cube_faces, binary=True)
        self.assert_filter_error(bad, [(FILTER_ENERGY, self.energy_params())], "NaN")
        self.assert_filter_error(bad, [(FILTER_SEED_PATH, self.seed_params("0,1"))], "NaN")

    # ------------------------------------------------------------------ the snake filters
    def snake_params(self, seeds, closed=False, method=0, out="", new_layer=True, use_quality=False, **kw):
        p = {"Seeds": seeds, "Closed": closed, "Alpha": 0.05, "Beta": 0.5, "Gamma": 1.0, "ExternalWeight": 1.0,
             "Spacing": 1.0, "MaxOperations": 500, "Method": method, "UseQuality": use_quality,
             "OutputFile": out, "NewLayer": new_layer}
        p.update(kw)
        return p

    def icocube_seeds(self, offset):
        return mlhost.cube_edge_seeds(os.path.join(DATA, "icocube.ply"), offset)

    @staticmethod
    def dist_to_edge(p):
        return math.hypot(1.0 - p[0], 1.0 - p[1])  # the cube edge x = y = 1

    def test_snake_converges_onto_cube_edge_json(self):
        """The batch filter through meshlabserver: the snake started 2.5 edge lengths off the
        edge ends on it; the JSON output follows the documented contract."""
        seeds, h = self.icocube_seeds(2.5)
        out_json = self.path("snake.json")
        rc, out = self.run_script(os.path.join(DATA, "icocube.ply"),
                                  [(FILTER_SNAKE, self.snake_params(",".join(map(str, seeds)), out=out_json))],
                                  outputs=[["-o", self.path("out.ply"), "-m", "vq"]])
        self.assertRegex(out, r"Geometric snake \(open, local embedding\): \d+ samples, \d+ operations, converged")
        with open(out_json) as f:
            j = json.load(f)
        for key in ("closed", "initial", "samples", "polyline", "stats"):
            self.assertIn(key, j)
        self.assertFalse(j["closed"])
        for key in ("operations", "updates", "embeddings", "converged", "seconds_total", "ms_per_embedding",
                    "ms_per_update", "ms_per_operation"):
            self.assertIn(key, j["stats"])
        self.assertTrue(j["stats"]["converged"])
        self.assertGreater(j["stats"]["embeddings"], 0)
        for s in j["samples"]:
            self.assertEqual(set(s), {"face", "bary", "position", "fixed"})
            self.assertAlmostEqual(sum(s["bary"]), 1.0, places=6)
        initial = [self.dist_to_edge(s["position"]) / h for s in j["initial"]["samples"]]
        final = sorted(self.dist_to_edge(s["position"]) / h for s in j["samples"])
        self.assertGreater(sum(initial) / len(initial), 1.5)
        # the mesh cuts the exact edge like a chamfer up to ~0.45 h deep: nothing on it is closer
        self.assertLess(final[int(0.95 * (len(final) - 1))], 0.6, final)
        self.assertGreater(len(j["polyline"]), len(j["samples"]))  # edge crossings included
        for p in j["polyline"]:
            self.assertTrue(all(math.isfinite(c) for c in p))

    def test_snake_projection_method_obj_and_export_filter(self):
        """Method 1 writes an OBJ with l records; the snake is kept on the mesh, and the export
        filter writes it again (PLY with an edge element) in the same script."""
        seeds, h = self.icocube_seeds(2.0)
        out_obj, out_ply = self.path("snake.obj"), self.path("curves.ply")
        rc, out = self.run_script(os.path.join(DATA, "icocube.ply"),
                                  [(FILTER_SNAKE, self.snake_params(",".join(map(str, seeds)), method=1, out=out_obj,
                                                                    new_layer=False)),
                                   (FILTER_EXPORT, {"OutputFile": out_ply, "Which": 0, "NewLayer": True})],
                                  outputs=[["-o", self.path("out.ply")]])
        self.assertIn("3D update + projection", out)
        with open(out_obj) as f:
            lines = f.read().splitlines()
        verts = [l for l in lines if l.startswith("v ")]
        lrec = [l for l in lines if l.startswith("l ")]
        self.assertEqual(len(lrec), 1)
        self.assertEqual(len(lrec[0].split()) - 1, len(verts))
        self.assertRegex(out, r"Exported 1 geometric snake\(s\) from the mesh")
        with open(out_ply) as f:
            head = f.read()
        self.assertRegex(head, r"element edge \d+")
        nv = int(re.search(r"element vertex (\d+)", head).group(1))
        ne = int(re.search(r"element edge (\d+)", head).group(1))
        self.assertEqual(ne, nv - 1)

    def test_snake_balloon_parameter(self):
        """The Balloon parameter in MeshLab: a closed snake seeded on the cylinder's flat cap, 7 edge
        lengths inside the top rim, inflates onto the rim with Balloon = 0.3."""
        cyl = os.path.join(DATA, "icocylinder.ply")
        seeds, h = mlhost.cylinder_cap_seeds(cyl, 0.3)
        seeds = ",".join(map(str, seeds))
        out_json = self.path("balloon.json")
        rc, out = self.run_script(cyl, [(FILTER_SNAKE, self.snake_params(seeds, closed=True, out=out_json,
                                                                          Balloon=0.3))])
        with open(out_json) as f:
            j = json.load(f)
        self.assertTrue(j["stats"]["converged"])
        self.assertAlmostEqual(j["params"]["balloon"], 0.3, places=6)
        d = sorted(mlhost.cylinder_rim_distance(s["position"]) / h for s in j["samples"])
        self.assertLess(d[int(0.95 * (len(d) - 1))], 0.6, d)

    def test_snake_errors(self):
        seeds, _ = self.icocube_seeds(2.0)
        ok = ",".join(map(str, seeds))
        ico = os.path.join(DATA, "icocube.ply")
        self.assert_filter_error(ico, [(FILTER_SNAKE, self.snake_params(ok, Gamma=0.0))], "Gamma")
        self.assert_filter_error(ico, [(FILTER_SNAKE, self.snake_params(ok, Spacing=1e-6))], "Spacing")
        self.assert_filter_error(ico, [(FILTER_SNAKE, self.snake_params(ok, MaxOperations=-5))], "MaxOperations")
        self.assert_filter_error(ico, [(FILTER_SNAKE, self.snake_params("1, 999999"))], "does not exist")
        self.assert_filter_error(ico, [(FILTER_SNAKE, self.snake_params(ok, closed=True, out=self.path("x.txt")))],
                                 "format")
        # the icocube file has no quality: UseQuality must say so, not run on garbage
        self.assert_filter_error(ico, [(FILTER_SNAKE, self.snake_params(ok, use_quality=True))], "no vertex quality")
        self.assert_filter_error(ico, [(FILTER_EXPORT, {"OutputFile": self.path("e.json"), "Which": 0,
                                                        "NewLayer": False})], "holds no geometric snakes")

    def test_snake_on_quality_field(self):
        """Any quality MeshLab can compute drives a snake: energy filter first, UseQuality on."""
        seeds, h = self.icocube_seeds(2.0)
        out_json = self.path("q.json")
        self.run_script(os.path.join(DATA, "icocube.ply"),
                        [(FILTER_ENERGY, self.energy_params(2, 2, False)),
                         (FILTER_SNAKE, self.snake_params(",".join(map(str, seeds)), out=out_json, use_quality=True))],
                        outputs=[["-o", self.path("out.ply")]])
        with open(out_json) as f:
            j = json.load(f)
        final = [self.dist_to_edge(s["position"]) / h for s in j["samples"]]
        self.assertLess(sum(final) / len(final), 0.6)

    # ------------------------------------------------------------------ CAD parts, seeds as points
    # data/cad_block.ply: tests/cad_meshes.h's 60 x 40 x 20 block with a bore and a pocket, every
    # face triangulated from its boundary vertices only (GS_WRITE_DATA=1 test_cad_tessellation).
    CAD_TOP_SEEDS = ((6.0, 3.0, 20.0), (20.0, 2.0, 20.0), (35.0, 4.0, 20.0), (54.0, 3.0, 20.0))

    @staticmethod
    def dist_to_front_edge(p):
        return math.hypot(p[1], p[2] - 20.0)  # the block's top front edge y = 0, z = 20

    def assert_captures_front_edge(self, j, x0, x1):
        """p95 of the curve within 1% of the edge's length (0.6), >= 95% of [x0, x1] covered."""
        pl = j["polyline"]
        d = sorted(self.dist_to_front_edge(p) for p in pl)
        self.assertLessEqual(d[int(round(0.95 * (len(d) - 1)))], 0.6, d[-10:])
        covered = [False] * 200
        for a, b in zip(pl, pl[1:]):
            if self.dist_to_front_edge(a) > 0.6 or self.dist_to_front_edge(b) > 0.6:
                continue
            lo, hi = sorted((a[0], b[0]))
            for k in range(200):
                if lo <= x0 + (k + 0.5) * (x1 - x0) / 200 <= hi:
                    covered[k] = True
        self.assertGreaterEqual(sum(covered) / 200.0, 0.95)

    def test_cad_snake_from_seed_points(self):
        """Seeds as coordinates 2-4 units off an edge of a CAD tessellation (slivers, no vertex
        inside any face): the crease energy, chosen in the snake filter, captures the edge; the
        curve starts exactly at the given points; the JSON keeps `seeds` and adds `seed_points`."""
        cad = os.path.join(DATA, "cad_block.ply")
        out_json = self.path("cad.json")
        pts = "; ".join("%g %g %g" % p for p in self.CAD_TOP_SEEDS)
        rc, out = self.run_script(cad, [(FILTER_SNAKE, self.snake_params("", SeedPoints=pts, EnergyType=3,
                                                                         out=out_json))],
                                  outputs=[["-o", self.path("out.ply"), "-m", "vq"]])
        m = re.search(r"4 seed points from the SeedPoints coordinates, moved onto the surface by at most (\S+) ", out)
        self.assertTrue(m, out)
        self.assertLess(float(m.group(1)), 1e-4)
        self.assertIn("crease distance energy", out)
        with open(out_json) as f:
            j = json.load(f)
        self.assertEqual(j["seeds"], [])
        self.assertEqual(len(j["seed_points"]), 4)
        for sp, p in zip(j["seed_points"], self.CAD_TOP_SEEDS):
            self.assertEqual(set(sp), {"face", "bary", "position"})
            self.assertLess(math.dist(sp["position"], p), 1e-4)
        first = j["initial"]["samples"][0]["position"]
        last = j["initial"]["samples"][-1]["position"]
        self.assertLess(math.dist(first, self.CAD_TOP_SEEDS[0]), 1e-4)
        self.assertLess(math.dist(last, self.CAD_TOP_SEEDS[-1]), 1e-4)
        # the snake reads the crease energy at its samples: it captures the edge between the seeds
        self.assert_captures_front_edge(j, self.CAD_TOP_SEEDS[0][0], self.CAD_TOP_SEEDS[-1][0])
        self.assertTrue(j["stats"]["converged"])

    def test_cad_closed_snake_on_the_bore_rim(self):
        """A closed snake from points 2-3.5 off the bore's top rim (on the top face's slivers)
        captures the rim all round: p95 within 1% of the rim's length."""
        cad = os.path.join(DATA, "cad_block.ply")
        out_json = self.path("bore.json")
        pts = []
        for i in range(4):
            a, r = 2 * math.pi * i / 4 + 0.3, 6.0 + 2.0 + (i % 2) * 1.5
            pts.append((15.0 + r * math.cos(a), 20.0 + r * math.sin(a), 20.0))
        rc, out = self.run_script(cad, [(FILTER_SNAKE, self.snake_params("", SeedPoints="; ".join("%.6f %.6f %.6f" % p for p in pts),
                                                                         closed=True, EnergyType=3, out=out_json))])
        with open(out_json) as f:
            j = json.load(f)
        self.assertTrue(j["closed"])
        rim = [(15.0 + 6.0 * math.cos(2 * math.pi * k / 64), 20.0 + 6.0 * math.sin(2 * math.pi * k / 64), 20.0)
               for k in range(64)]

        def dist_rim(p):
            best = 1e9
            for k in range(64):
                a, b = rim[k], rim[(k + 1) % 64]
                d = [b[i] - a[i] for i in range(3)]
                t = max(0.0, min(1.0, sum((p[i] - a[i]) * d[i] for i in range(3)) / sum(x * x for x in d)))
                best = min(best, math.dist(p, [a[i] + d[i] * t for i in range(3)]))
            return best
        d = sorted(dist_rim(p) for p in j["polyline"])
        tol = 0.01 * 2 * 64 * 6.0 * math.sin(math.pi / 64)
        self.assertLessEqual(d[int(round(0.95 * (len(d) - 1)))], tol, d[-10:])
        angles = sorted(math.atan2(p[1] - 20.0, p[0] - 15.0) for p in j["polyline"])
        gaps = [b - a for a, b in zip(angles, angles[1:])] + [angles[0] + 2 * math.pi - angles[-1]]
        self.assertLess(max(gaps), 0.05 * 2 * math.pi)  # all round the rim

    def write_pick_points(self, path, pts):
        """A .pp file as MeshLab 2020.09's Pick Points writes it (PickedPoints::save: a
        QDomDocument saved with indent 1; QDom orders the attributes by hash)."""
        lines = ["<!DOCTYPE PickedPoints>", "<PickedPoints>", " <DocumentData>",
                 '  <DateTime time="05:01:02" date="2026-11-24"/>', '  <User name="root"/>',
                 '  <DataFileName name="cad_block.ply"/>', '  <templateName name=""/>', " </DocumentData>"]
        for i, p in enumerate(pts):
            lines.append(' <point y="%s" x="%s" active="1" z="%s" name="%d"/>' % (repr(p[1]), repr(p[0]), repr(p[2]), i))
        lines.append("</PickedPoints>")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")

    def test_cad_snake_from_pick_points_file(self):
        """The same from a Pick Points file, on the front face, with the seed path filter too."""
        cad = os.path.join(DATA, "cad_block.ply")
        pp = self.path("picked.pp")
        pts = [(8.0, 0.0, 17.0), (30.0, 0.0, 16.5), (52.0, 0.0, 17.5)]
        self.write_pick_points(pp, pts)
        out_json = self.path("cad_pp.json")
        rc, out = self.run_script(cad, [(FILTER_SEED_PATH, self.seed_params("", SeedFile=pp)),
                                        (FILTER_SNAKE, self.snake_params("", SeedFile=pp, EnergyType=3, out=out_json))],
                                  outputs=[["-o", self.path("out.ply")]])
        self.assertIn("3 seed points from the Pick Points file %s" % pp, out)
        self.assertRegex(out, r"Seed path \(open, length cost\) through 3 seeds")
        with open(out_json) as f:
            j = json.load(f)
        for sp, p in zip(j["seed_points"], pts):
            self.assertLess(math.dist(sp["position"], p), 1e-4)
        self.assert_captures_front_edge(j, pts[0][0], pts[-1][0])

    def test_seed_points_errors(self):
        cad = os.path.join(DATA, "cad_block.ply")
        bad_pp = self.path("bad.pp")
        with open(bad_pp, "w") as f:
            f.write("<PickedPoints><point x=\"1\" y=\"oops\" z=\"3\"/></PickedPoints>\n")
        fifo = self.path("fifo.pp")
        os.mkfifo(fifo)
        for params, msg in (({"SeedPoints": "1 2 three; 4 5 6"}, "unexpected character"),
                            ({"SeedPoints": "6 3 20; nan 2 20"}, "finite"),
                            ({"SeedPoints": "6 3 20"}, "at least 2 seed points"),
                            ({"SeedPoints": "6 3 20; 30 2 90"}, "farther than 10% of the bounding box diagonal"),
                            ({"SeedFile": self.path("missing.pp")}, "Cannot read the Pick Points file"),
                            ({"SeedFile": fifo}, "not a regular file"),  # issue 36: a FIFO blocked forever
                            ({"SeedFile": bad_pp}, "Not a MeshLab Pick Points"),
                            ({"SeedPoints": "6 3 20; 30 2 20", "SeedFile": bad_pp}, "use one of them"),
                            ({}, "No seeds given")):
            with self.subTest(params=params):
                self.assert_filter_error(cad, [(FILTER_SNAKE, self.snake_params("", EnergyType=3, **params))], msg)
        self.assert_filter_error(cad, [(FILTER_SNAKE, self.snake_params("", SeedPoints="6 3 20; 54 3 20",
                                                                        CreaseAngle=0.0))], "CreaseAngle")

    def test_triangle_soup(self):
        """A soup (every face with its own vertices, as STL stores it) is refused with a message
        naming Merge Close Vertices; merged on request with a Log line."""
        ply = mlhost.read_ply(os.path.join(DATA, "cad_block.ply"))
        pts = [(v["x"], v["y"], v["z"]) for v in ply.vertices]
        verts, faces = [], []
        for f in ply.faces:
            idx = next(iter(f.values()))
            faces.append([len(verts), len(verts) + 1, len(verts) + 2])
            verts += [pts[i] for i in idx]
        soup = self.path("soup.ply")
        mlhost.write_ply(soup, verts, faces)
        seeds = "; ".join("%g %g %g" % p for p in self.CAD_TOP_SEEDS)
        self.assert_filter_error(soup, [(FILTER_SNAKE, self.snake_params("", SeedPoints=seeds, EnergyType=3))],
                                 "triangle soup.*Merge Close Vertices")
        rc, out = self.run_script(soup, [(FILTER_SNAKE, self.snake_params("", SeedPoints=seeds, EnergyType=3,
                                                                          MergeDuplicateVertices=True))])
        self.assertRegex(out, r"The mesh was a triangle soup: merged %d duplicate vertices \(%d -> %d vertices"
                         % (len(verts) - len(pts), len(verts), len(pts)))

    # ------------------------------------------------------------------ cut (issue 34)
    def test_cut_filter_selects_the_inside_of_a_snake_file(self):
        """The square snake on a flat plate: the selected faces (quality 1) cover area 25 exactly;
        split makes two layers; a curve of another mesh is refused."""
        mesh, curve, data = mlhost.plate_and_square(self.work)
        out = self.path("cut.ply")
        rc, log = self.run_script(mesh, [(FILTER_CUT, {"CurveFile": curve})], outputs=[["-o", out, "-m", "fq"]])
        self.assertRegex(log, r"Cut \(select\) along a closed snake")
        ply = mlhost.read_ply(out)
        area = mlhost.inside_area(ply)
        self.assertAlmostEqual(area, 25.0, places=5)
        self.assertGreater(len(ply.faces), 200)
        rc, log = self.run_script(mesh, [(FILTER_CUT, {"CurveFile": curve, "Split": True})])
        self.assertRegex(log, r"Cut \(split\) along a closed snake")
        data["samples"][1]["position"] = [9, 9, 9]
        bad = self.path("moved.json")
        with open(bad, "w") as f:
            json.dump(data, f)
        self.assert_filter_error(mesh, [(FILTER_CUT, {"CurveFile": bad})], "made on another mesh")
        self.assert_filter_error(mesh, [(FILTER_CUT, {})], "No snake to cut along")

    def test_unknown_filter_is_detected(self):
        """The harness itself: a filter MeshLab does not know (e.g. its plugin failed to load)
        makes meshlabserver fail, so every other test would fail too."""
        mlx = self.path("unknown.mlx")
        mlhost.write_mlx(mlx, [("Geometric Snake Filter That Does Not Exist", {})])
        rc, out = mlhost.run_meshlabserver(["-i", self.cube, "-o", self.path("u.ply"), "-s", mlx], cwd=self.work)
        self.assertNotEqual(rc, 0, out)
        self.assertIn("not found", out)


if __name__ == "__main__":
    unittest.main()
