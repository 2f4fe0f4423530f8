#!/usr/bin/env python3
"""Tests of the geometric-snake program (cli/): options, outputs, every error case of the
host tests, safe writes, --json-log, the progress bar, --batch. No MeshLab needed.

CTest registers every `def test_*` below as its own test `cli_<name>` (label `cli`).
Run one by hand:  GS_CLI=build/cli/geometric-snake python3 tests/cli/test_cli.py -v CliTests.test_help

Environment: GS_CLI (the program), GS_DATA_DIR (repo data/), GS_CLI_WORK (scratch folder).
"""

import json
import math
import os
import pty
import re
import subprocess
import sys
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "host"))
import mlhost  # noqa: E402

CLI = os.environ.get("GS_CLI", "geometric-snake")
DATA = os.environ.get("GS_DATA_DIR", os.path.join(HERE, "..", "..", "data"))
ICO = os.path.join(DATA, "icocube.ply")
N = 8


def run(args, **kw):
    p = subprocess.run([CLI] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                       timeout=kw.pop("timeout", 300), **kw)
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")


def ico_seeds(offset=2.5):
    seeds, h = mlhost.cube_edge_seeds(ICO, offset)
    return ",".join(map(str, seeds)), h


class CliTests(mlhost.WorkDirTestCase):
    WORK_ENV = "GS_CLI_WORK"

    def setUp(self):
        super().setUp()
        self.write_cube(N)

    def cube_index(self, p):
        return self.cube_verts.index(tuple(float(c) for c in p))

    def ok(self, args):
        rc, out, err = run(args)
        self.assertEqual(rc, 0, "geometric-snake %s failed:\n%s%s" % (" ".join(args), out, err))
        self.assertNotIn("\r", err, "no progress bar when stderr is not a terminal")
        return out, err

    def assert_error(self, args, regex, status=1, outputs=()):
        """Fails with `status`, says `regex` on stderr, leaves no output and no temporary file."""
        before = set(os.listdir(self.work))
        rc, out, err = run(args)
        self.assertEqual(rc, status, "expected exit status %d, got %d:\n%s%s" % (status, rc, out, err))
        self.assertRegex(err, regex)
        self.assertNotIn("Internal error", err)
        after = set(os.listdir(self.work))
        self.assertEqual(after - before, set(), "a failed run left files behind")
        for o in outputs:
            self.assertFalse(os.path.exists(o), o)
        return err

    # ------------------------------------------------------------------ help
    def test_help_lists_every_option(self):
        out, _ = self.ok(["--help"])
        for cmd in ("energy", "snake", "path"):
            self.assertIn("geometric-snake %s MESH [--" % cmd, out)
        for opt in ("--type", "--smoothing", "--colorize", "--seeds", "--closed", "--cost", "--alpha", "--beta",
                    "--gamma", "--external-weight", "--balloon", "--spacing", "--max-operations", "--method", "--use-quality",
                    "--mesh-out", "--json-log", "--batch", "--jobs", "-o, --output"):
            self.assertIn(opt, out)
        # Defaults and ranges come from the shared definition (the filters' parameters).
        flat = " ".join(out.split())
        self.assertRegex(flat, r"--alpha X .*?Range \[0, 10000\]\. Default: 0\.05\.")
        self.assertRegex(flat, r"--gamma X .*?Range \(0, 1000000\]\. Default: 1\.")
        self.assertRegex(flat, r"--max-operations N .*?Range \[0, 1000000\]\. Default: 500\.")
        self.assertIn("[MeshLab parameter ExternalWeight]", flat)
        out, _ = self.ok(["snake", "--help"])
        self.assertIn("--spacing", out)
        self.assertNotIn("--smoothing", out)
        rc, out, err = run([])
        self.assertEqual(rc, 2)
        self.assertIn("usage:", err)

    # ------------------------------------------------------------------ outputs
    def test_energy_writes_quality_and_colour(self):
        out_ply = self.path("e.ply")
        for t in ("normal", "curvature", "quadric"):
            with self.subTest(type=t):
                self.ok(["energy", self.cube, "--type", t, "--smoothing", "0", "-o", out_ply])
                ply = mlhost.read_ply(out_ply)
                self.assertEqual(len(ply.vertices), len(self.cube_verts))
                self.assertEqual(len(ply.faces), len(self.cube_faces))
                q = [v["quality"] for v in ply.vertices]
                self.assertTrue(all(math.isfinite(x) and -1e-6 <= x <= 1 + 1e-6 for x in q))
                pts = [(v["x"], v["y"], v["z"]) for v in ply.vertices]
                edge = [qq for p, qq in zip(pts, q) if mlhost.on_cube_edge(p)]
                flat = [qq for p, qq in zip(pts, q) if mlhost.cube_edge_distance(p) > 1.5 / N]
                self.assertLess(max(edge), min(flat) - 0.3)
                for v in ply.vertices:
                    if v["quality"] < 0.1:
                        self.assertGreater(v["red"], v["blue"])
        self.ok(["energy", self.cube, "--no-colorize", "-o", out_ply])
        self.assertNotIn("red", mlhost.read_ply(out_ply).vertices[0])

    def test_snake_json_obj_ply(self):
        seeds, h = ico_seeds(2.5)
        out_json = self.path("s.json")
        out, err = self.ok(["snake", ICO, "--seeds", seeds, "-o", out_json])
        self.assertRegex(err, r"Geometric snake \(open, local embedding\): \d+ samples, \d+ operations, converged")
        j = json.load(open(out_json))
        for key in ("closed", "initial", "samples", "polyline", "params", "stats"):
            self.assertIn(key, j)
        self.assertTrue(j["stats"]["converged"])
        final = sorted(math.hypot(1 - s["position"][0], 1 - s["position"][1]) / h for s in j["samples"])
        self.assertLess(final[int(0.95 * (len(final) - 1))], 0.6, final)
        self.assertAlmostEqual(j["params"]["alpha"], 0.05, places=6)
        # OBJ: one l record through every vertex; PLY: vertex + edge elements.
        self.ok(["snake", ICO, "--seeds", seeds, "--method", "projection", "-o", self.path("s.obj")])
        lines = open(self.path("s.obj")).read().splitlines()
        lrec = [l for l in lines if l.startswith("l ")]
        self.assertEqual(len(lrec), 1)
        self.assertEqual(len(lrec[0].split()) - 1, len([l for l in lines if l.startswith("v ")]))
        self.ok(["snake", ICO, "--seeds", seeds, "--closed=off", "-o", self.path("s.ply")])
        head = open(self.path("s.ply")).read()
        nv = int(re.search(r"element vertex (\d+)", head).group(1))
        ne = int(re.search(r"element edge (\d+)", head).group(1))
        self.assertEqual(ne, nv - 1)

    def test_balloon_inflates_onto_the_rim(self):
        """--balloon: a closed snake seeded on the flat cap of the cylinder, 7 edge lengths inside
        its top rim, inflates onto the rim; out of range is refused with the range."""
        cyl = os.path.join(DATA, "icocylinder.ply")
        seeds, h = mlhost.cylinder_cap_seeds(cyl, 0.3)
        seeds = ",".join(map(str, seeds))
        self.ok(["snake", cyl, "--seeds", seeds, "--closed", "--balloon", "0.3", "-o", self.path("b.json")])
        with open(self.path("b.json")) as f:
            j = json.load(f)
        self.assertTrue(j["stats"]["converged"])
        self.assertAlmostEqual(j["params"]["balloon"], 0.3, places=6)
        d = sorted(mlhost.cylinder_rim_distance(s["position"]) / h for s in j["samples"])
        self.assertLess(d[int(0.95 * (len(d) - 1))], 0.6, d)
        self.assert_error(["snake", cyl, "--seeds", seeds, "--closed", "--balloon", "11", "-o", self.path("x.json")],
                          r"--balloon must be in \[-10, 10\], not 11", outputs=[self.path("x.json")])

    def test_snake_mesh_out_and_use_quality(self):
        """--mesh-out writes the energy in the quality; --use-quality runs on a file's quality."""
        seeds, h = ico_seeds(2.0)
        q_ply = self.path("q.ply")
        self.ok(["energy", ICO, "--type", "quadric", "-o", q_ply])
        self.ok(["snake", q_ply, "--seeds", seeds, "--use-quality", "-o", self.path("q.json"),
                 "--mesh-out", self.path("m.ply")])
        j = json.load(open(self.path("q.json")))
        final = [math.hypot(1 - s["position"][0], 1 - s["position"][1]) / h for s in j["samples"]]
        self.assertLess(sum(final) / len(final), 0.6)
        q = [v["quality"] for v in mlhost.read_ply(self.path("m.ply")).vertices]
        self.assertLess(min(q), 0.05)

    def test_every_output_mesh_keeps_the_input_attributes(self):
        """Colours, per-vertex and per-wedge texture coordinates and normals of the input survive
        `energy -o` and `snake --mesh-out` alike (issue 36: --mesh-out dropped the texture coordinates)."""
        v, f = self.cube_verts, self.cube_faces
        src = self.path("colors_tex.ply")
        with open(src, "w") as o:
            o.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                    "property float nx\nproperty float ny\nproperty float nz\n"
                    "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
                    "property float texture_u\nproperty float texture_v\nelement face %d\n"
                    "property list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n"
                    % (len(v), len(f)))
            for i, p in enumerate(v):
                o.write("%r %r %r 0 0 1 %d 20 30 255 %r %r\n" % (p + (i % 256, p[0], p[1])))
            for t in f:
                o.write("3 %d %d %d 6 %s\n" % (t + (" ".join("%r %r" % (v[i][0], v[i][2]) for i in t),)))
        a, b = self.cube_index((0.0, 0.0, 0.0)), self.cube_index((1.0, 0.0, 0.0))
        self.ok(["energy", src, "-o", self.path("e.ply"), "--no-colorize"])
        self.ok(["snake", src, "--seeds", "%d,%d" % (a, b), "-o", self.path("s.json"), "--mesh-out", self.path("m.ply")])
        for out in ("e.ply", "m.ply"):
            with self.subTest(output=out):
                ply = mlhost.read_ply(self.path(out))
                vk, fk = set(ply.vertices[0]), set(ply.faces[0])
                for k in ("quality", "red", "texture_u", "texture_v", "nx"):
                    self.assertIn(k, vk)
                self.assertIn("texcoord", fk)
                self.assertEqual(len(ply.vertices), len(v))
                for i, row in enumerate(ply.vertices):
                    self.assertAlmostEqual(row["texture_u"], v[i][0], places=5)
                    self.assertEqual(row["red"], i % 256)

    def test_path_along_cube_edge(self):
        a, b = self.cube_index((0.0, 0.0, 0.0)), self.cube_index((1.0, 0.0, 0.0))
        out, err = self.ok(["path", self.cube, "--seeds", "%d, %d" % (a, b), "-o", self.path("p.ply"), "--json-log"])
        log = json.loads(out)
        self.assertEqual(log["path_vertices"], N + 1)
        self.assertAlmostEqual(log["length"], 1.0, places=5)
        ply = mlhost.read_ply(self.path("p.ply"))
        xs = [v["x"] for v in ply.vertices]
        self.assertEqual(xs, sorted(xs))
        self.assertEqual(len(ply.elements["edge"]), N)
        for v in ply.vertices:
            self.assertAlmostEqual(v["y"], 0.0, places=5)
            self.assertAlmostEqual(v["z"], 0.0, places=5)
        # Closed feature-cost loop, as JSON (vertex indices) and OBJ (l records).
        seeds = [self.cube_index(p) for p in ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0))]
        self.ok(["path", self.cube, "--seeds", ",".join(map(str, seeds)), "--closed", "--cost", "feature",
                 "-o", self.path("loop.json")])
        j = json.load(open(self.path("loop.json")))
        self.assertTrue(j["closed"])
        self.assertEqual(len(j["vertices"]), 4 * N)
        self.ok(["path", self.cube, "--seeds", ",".join(map(str, seeds)), "--closed", "-o", self.path("loop.obj")])
        self.assertEqual(sum(1 for l in open(self.path("loop.obj")) if l.startswith("l ")), 4 * N)

    def test_reads_off_obj_stl(self):
        """The same cube as PLY, OFF, OBJ and STL (vcglib's importers) gives the same energy."""
        v, f = self.cube_verts, self.cube_faces
        with open(self.path("cube.off"), "w") as o:
            o.write("OFF\n%d %d 0\n" % (len(v), len(f)))
            o.writelines("%r %r %r\n" % p for p in v)
            o.writelines("3 %d %d %d\n" % t for t in f)
        with open(self.path("cube.obj"), "w") as o:
            o.writelines("v %r %r %r\n" % p for p in v)
            o.writelines("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1) for t in f)
        with open(self.path("cube.stl"), "w") as o:
            o.write("solid cube\n")
            for t in f:
                o.write("facet normal 0 0 0\nouter loop\n")
                o.writelines("vertex %r %r %r\n" % v[i] for i in t)
                o.write("endloop\nendfacet\n")
            o.write("endsolid cube\n")
        ref = None
        for ext in ("ply", "off", "obj", "stl"):
            with self.subTest(format=ext):
                out, _ = self.ok(["energy", self.path("cube." + ext), "-o", self.path("e_%s.ply" % ext), "--json-log"])
                log = json.loads(out)
                self.assertEqual(log["vertices"], len(v))
                self.assertEqual(log["faces"], len(f))
                q = sorted(x["quality"] for x in mlhost.read_ply(self.path("e_%s.ply" % ext)).vertices)
                if ref is None:
                    ref = q
                for a, b in zip(ref, q):
                    self.assertAlmostEqual(a, b, places=5)

    def test_obj_loads_whole_or_is_refused(self):
        """vcglib's OBJ importer drops the faces at vertex 1 and crashes on a far index: the program
        checks every index first and rebuilds the faces the importer dropped (issue 36)."""
        tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
        with open(self.path("tet.obj"), "w") as o:
            o.write(tet + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
        out, _ = self.ok(["energy", self.path("tet.obj"), "-o", self.path("tet.ply"), "--json-log"])
        self.assertEqual(json.loads(out)["faces"], 4)
        faces = sorted(tuple(sorted(f["vertex_indices"])) for f in mlhost.read_ply(self.path("tet.ply")).faces)
        self.assertEqual(faces, [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)])
        # relative (negative) indices, a quad (two triangles) and texture coordinates at vertex 1
        with open(self.path("quad.obj"), "w") as o:
            o.write(tet + "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nf -4/1 -2/3 -3/2\nf 1/1 2/2 4/4 3/3\n")
        out, _ = self.ok(["energy", self.path("quad.obj"), "-o", self.path("quad.ply"), "--json-log"])
        self.assertEqual(json.loads(out)["faces"], 3)
        ply = mlhost.read_ply(self.path("quad.ply"))
        self.assertEqual(len(ply.faces), 3)
        self.assertTrue(any("texcoord" in k or "texture" in k for k in ply.elements["face"][0].keys() |
                            ply.elements["vertex"][0].keys()), "the texture coordinates are kept")
        out = self.path("never.ply")
        for body, why in (("f 1 2 100000", r"line 6 \(\"f 1 2 100000\"\) refers to vertex 100000, but only 4"),
                          ("f 1 2 -9", "refers to vertex -9"), ("f 0 1 2", "refers to vertex 0"),
                          ("f 1 2 99999999999999999999", "bad vertex index"), ("f 1 2", "fewer than 3 vertices"),
                          ("f 1/7 2/1 3/1", "texture coordinate 7"), ("l 1 9", "refers to vertex 9")):
            with self.subTest(face=body):
                with open(self.path("bad.obj"), "w") as o:
                    o.write(tet + "vt 0 0\n" + body + "\nf 2 3 4\n")
                for cmd in (["energy"], ["path", "--seeds", "1,2"], ["snake", "--seeds", "1,2"]):
                    self.assert_error([cmd[0], self.path("bad.obj")] + cmd[1:] + ["-o", out], why)

    def test_json_log_is_one_line(self):
        seeds, _ = ico_seeds(2.0)
        out, err = self.ok(["snake", ICO, "--seeds", seeds, "--json-log", "-q"])
        self.assertEqual(err, "")
        lines = out.splitlines()
        self.assertEqual(len(lines), 1)
        log = json.loads(lines[0])
        for key in ("ok", "command", "mesh", "vertices", "faces", "samples", "operations", "converged",
                    "ms_per_operation", "seconds_total", "length", "warnings"):
            self.assertIn(key, log)
        self.assertTrue(log["ok"])
        self.assertEqual(log["parameters"]["method"], "embedding")
        self.assertEqual(log["parameters"]["max-operations"], 500)
        self.assertEqual(log["parameters"]["seeds"], seeds)
        rc, out, err = run(["snake", ICO, "--seeds", "1, 999999", "--json-log"])
        self.assertEqual(rc, 1)
        log = json.loads(out)
        self.assertFalse(log["ok"])
        self.assertIn("does not exist", log["error"])

    def test_progress_bar_only_on_a_terminal(self):
        seeds, _ = ico_seeds(2.0)
        master, slave = pty.openpty()
        p = subprocess.Popen([CLI, "snake", ICO, "--seeds", seeds, "-o", self.path("t.json")],
                             stdout=subprocess.DEVNULL, stderr=slave, stdin=subprocess.DEVNULL)
        os.close(slave)
        chunks = []
        while True:
            try:
                b = os.read(master, 4096)
            except OSError:
                break
            if not b:
                break
            chunks.append(b)
        self.assertEqual(p.wait(timeout=120), 0)
        os.close(master)
        text = b"".join(chunks).decode("utf-8", "replace")
        self.assertRegex(text, r"\rsnake \[#+ *\] +\d+%")
        # Not a terminal: self.ok() checks there is no \r at all.
        self.ok(["snake", ICO, "--seeds", seeds, "-o", self.path("t.json")])

    def test_seed_points_and_pick_points_file(self):
        """--seed-points and --pp (MeshLab Pick Points): seeds snapped onto the surface; the path
        starts exactly there, the snake lands on the icocube edge."""
        _, h = ico_seeds(2.0)
        targets = [(1.0, 1.0 - 2.0 * h, z) for z in (-0.6, -0.2, 0.2, 0.6)]
        text = "; ".join("%r %r %r" % t for t in targets)
        out, err = self.ok(["snake", ICO, "--seed-points", text, "-o", self.path("sp.json"), "--json-log"])
        self.assertIn("4 seed points from the SeedPoints coordinates", err)
        j = json.load(open(self.path("sp.json")))
        final = sorted(math.hypot(1 - s["position"][0], 1 - s["position"][1]) / h for s in j["samples"])
        self.assertLess(final[int(0.95 * (len(final) - 1))], 0.6, final)
        with open(self.path("seeds.pp"), "w") as f:
            f.write("<!DOCTYPE PickedPoints>\n<PickedPoints>\n")
            for i, t in enumerate(targets):
                f.write(' <point x="%r" y="%r" z="%r" active="1" name="%d"/>\n' % (t + (i,)))
            f.write(' <point x="0" y="0" z="0" active="0" name="unplaced"/>\n</PickedPoints>\n')
        self.ok(["path", ICO, "--pp", self.path("seeds.pp"), "-o", self.path("pp.json")])
        pl = json.load(open(self.path("pp.json")))["polyline"]
        self.assertLess(math.dist(pl[0], targets[0]), 0.05 * h)  # the icocube face holds the point
        self.assertLess(math.dist(pl[-1], targets[-1]), 0.05 * h)
        self.ok(["snake", ICO, "--pp", self.path("seeds.pp"), "-o", self.path("pp_snake.json")])
        # Vertex seeds win over points, with a warning; both point sources at once is an error.
        seeds, _ = ico_seeds(2.0)
        out, err = self.ok(["path", ICO, "--seeds", seeds, "--seed-points", text, "-o", self.path("w.ply")])
        self.assertIn("are ignored", err)
        self.assert_error(["snake", ICO, "--seed-points", text, "--pp", self.path("seeds.pp"), "-o",
                           self.path("never.json")], "Both SeedPoints and SeedFile")
        self.assert_error(["snake", ICO, "--pp", self.path("missing.pp"), "-o", self.path("never.json")], "missing.pp")
        self.assert_error(["snake", ICO, "-o", self.path("never.json")], "No seeds given")
        self.assert_error(["snake", ICO, "--seed-points", "1 2", "-o", self.path("never.json")], "seed")

    def test_soup_and_crease_energy(self):
        """A triangle soup is refused unless --merge-duplicates; --type crease finds the cube's edges."""
        soup_v, soup_f = [], []
        for t in self.cube_faces:
            soup_f.append(tuple(range(len(soup_v), len(soup_v) + 3)))
            soup_v += [self.cube_verts[i] for i in t]
        mlhost.write_ply(self.path("soup.ply"), soup_v, soup_f)
        self.assert_error(["energy", self.path("soup.ply"), "-o", self.path("never.ply")], "triangle soup")
        out, err = self.ok(["energy", self.path("soup.ply"), "--merge-duplicates", "-o", self.path("m.ply"),
                            "--json-log"])
        self.assertIn("merged", err)
        self.assertEqual(len(mlhost.read_ply(self.path("m.ply")).vertices), len(self.cube_verts))
        out, err = self.ok(["energy", self.cube, "--type", "crease", "-o", self.path("c.ply"), "--json-log"])
        self.assertEqual(json.loads(out)["creases"], 12 * N)
        self.assert_error(["energy", self.cube, "--type", "crease", "--crease-angle", "200", "-o",
                           self.path("never.ply")], "--crease-angle must be in")

    # ------------------------------------------------------------------ errors (those of the host tests)
    def test_error_bad_seeds(self):
        out = self.path("never.ply")
        for seeds, msg in (("0, x", "Cannot read the seed list"), ("", "No seeds"), ("5", "at least 2"),
                           ("0, 99999", "does not exist")):
            with self.subTest(seeds=seeds):
                self.assert_error(["path", self.cube, "--seeds", seeds, "-o", out], msg, outputs=[out])

    def test_error_bad_smoothing_steps(self):
        out = self.path("never.ply")
        for steps in ("-1", "10001", "2000000000"):
            with self.subTest(steps=steps):
                self.assert_error(["energy", self.cube, "--smoothing", steps, "-o", out],
                                  r"--smoothing must be in \[0, 10000\], not " + steps, outputs=[out])
        self.assert_error(["energy", self.cube, "--smoothing", "2.5", "-o", out], "--smoothing expects an integer")
        self.assert_error(["energy", self.cube, "--type", "fancy", "-o", out],
                          r"--type expects one of normal\|curvature\|quadric")

    def test_error_point_cloud(self):
        pc = self.path("pc.ply")
        mlhost.write_ply(pc, self.cube_verts, None)
        self.assert_error(["energy", pc, "-o", self.path("never.ply")], "point cloud")
        self.assert_error(["path", pc, "--seeds", "0,1", "-o", self.path("never.ply")], "point cloud")

    def test_error_empty_mesh(self):
        empty = self.path("empty.ply")
        mlhost.write_ply(empty, [], [])
        self.assert_error(["energy", empty, "-o", self.path("never.ply")], "empty")

    def test_error_nan_coordinates(self):
        verts = list(self.cube_verts)
        verts[3] = (float("nan"), 0.5, 0.5)
        bad = self.path("nan.ply")
        mlhost.write_ply(bad, verts, self.cube_faces, binary=True)
        self.assert_error(["energy", bad, "-o", self.path("never.ply")], "NaN")
        self.assert_error(["path", bad, "--seeds", "0,1", "-o", self.path("never.ply")], "NaN")

    def test_error_snake(self):
        seeds, _ = ico_seeds(2.0)
        out = self.path("never.json")
        self.assert_error(["snake", ICO, "--seeds", seeds, "--gamma", "0", "-o", out], r"--gamma must be in \(0,")
        self.assert_error(["snake", ICO, "--seeds", seeds, "--spacing", "1e-6", "-o", out], "--spacing must be in")
        self.assert_error(["snake", ICO, "--seeds", seeds, "--max-operations", "-5", "-o", out],
                          "--max-operations must be in")
        self.assert_error(["snake", ICO, "--seeds", "1, 999999", "-o", out], "does not exist")
        self.assert_error(["snake", ICO, "--seeds", seeds, "--closed", "-o", self.path("x.txt")], "format")
        self.assert_error(["snake", ICO, "--seeds", seeds, "--use-quality", "-o", out], "no vertex quality")
        self.assert_error(["snake", ICO, "--seeds", seeds, "--alpha", "abc", "-o", out], "--alpha expects a number")
        self.assert_error(["snake", ICO, "--seeds", seeds, "--method", "2", "-o", out], "--method expects one of")

    def test_error_command_line(self):
        out = self.path("never.ply")
        self.assert_error(["energy", self.cube, "--bogus", "1", "-o", out], "has no option --bogus", status=2)
        self.assert_error(["frobnicate", self.cube], "unknown command", status=2)
        self.assert_error(["energy", self.cube], "No output file", status=2)
        self.assert_error(["energy", "-o", out], "No mesh given", status=2)
        self.assert_error(["energy", self.cube, "-o"], "needs a value", status=2)
        self.assert_error(["snake", self.cube, "--seeds", "0,1"], "Nothing to write", status=2)

    def test_error_files(self):
        out = self.path("never.ply")
        self.assert_error(["energy", self.path("missing.ply"), "-o", out], "Cannot (open|read) the mesh.*No such file")
        with open(self.path("junk.ply"), "w") as f:
            f.write("this is not a ply file\n")
        self.assert_error(["energy", self.path("junk.ply"), "-o", out], "Cannot read the mesh")
        with open(self.path("junk.obj"), "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nf 1 2 7\n")
        self.assert_error(["energy", self.path("junk.obj"), "-o", out],
                          r"line 3 \(\"f 1 2 7\"\) refers to vertex 7, but only 2 vertices are defined")
        self.assert_error(["energy", self.path("cube.3ds"), "-o", out], "Cannot (open|read) the mesh.*No such file")
        self.assert_error(["energy", self.cube, "-o", self.path("nofolder/e.ply")], "does not exist")
        self.assert_error(["energy", self.cube, "-o", self.path("e.off")], "unknown format")
        for name, text in (("empty.stl", ""), ("noline.stl", "solid x"), ("empty.off", ""), ("empty.ply", "")):
            with open(self.path(name), "w") as f:  # vcglib's ASCII STL reader never returns on these
                f.write(text)
            self.assert_error(["energy", self.path(name), "-o", out], "Cannot read the mesh")

    def test_non_regular_inputs_refused_at_once(self):
        """A FIFO, a device or a folder given as any input is refused at once, never read (issue 36:
        a FIFO .pp blocked the program forever)."""
        fifo = self.path("fifo")
        os.mkfifo(fifo)
        out = self.path("never.ply")
        t0 = time.time()
        for args, what in ((["energy", fifo + ".ply"], "the mesh"),
                           (["snake", self.cube, "--pp", fifo, "--json-log"], "the Pick Points file"),
                           (["path", self.cube, "--pp", "/dev/zero"], "the Pick Points file"),
                           (["snake", self.cube, "--pp", self.work, "--json-log"], "the Pick Points file")):
            with self.subTest(args=args):
                if args[1] == fifo + ".ply":
                    os.mkfifo(args[1])
                rc, o, err = run(args + ["-o", out], timeout=20)
                self.assertEqual(rc, 1, err)
                self.assertRegex(err, "Cannot read %s .*(not a regular file|a folder)" % what)
        rc, o, err = run(["--batch", fifo], timeout=20)
        self.assertEqual(rc, 1, err)
        self.assertRegex(err, "Cannot read the batch file .*not a regular file")
        self.assertLess(time.time() - t0, 15)

    def test_never_writes_the_session_files(self):
        """The edit tool's session file, its backup and recovered sessions are the user's: the
        program refuses them as outputs, as the filters and the tool do (issue 36)."""
        a, b = self.cube_index((0.0, 0.0, 0.0)), self.cube_index((1.0, 0.0, 0.0))
        for suffix in (".snakes.json", ".snakes.recovered-20260101-120000.json"):
            with self.subTest(suffix=suffix):
                side = self.cube + suffix
                with open(side, "w") as f:
                    f.write('{"precious": true}\n')
                self.assert_error(["snake", self.cube, "--seeds", "%d,%d" % (a, b), "-o", side],
                                  "Refusing to write .*(session)")
                self.assert_error(["path", self.cube, "--seeds", "%d,%d" % (a, b), "-o", side],
                                  "Refusing to write")
                self.assertEqual(open(side).read(), '{"precious": true}\n')
        # the sidecar of a mesh not yet saved is refused too (the tool would write it)
        os.remove(self.cube + ".snakes.json")
        self.assert_error(["path", self.cube, "--seeds", "%d,%d" % (a, b), "-o", self.path("cube.ply.snakes.json")],
                          "Refusing to write")

    def test_killed_runs_leave_no_temporary_file(self):
        """ulimit -f (SIGXFSZ) while writing, SIGTERM and SIGINT while running, --timeout: no file is left
        behind and stderr says why; a later write removes what a killed run left (issue 36)."""
        import resource
        import signal
        a, b = self.cube_index((0.0, 0.0, 0.0)), self.cube_index((1.0, 0.0, 0.0))
        limit = lambda: resource.setrlimit(resource.RLIMIT_FSIZE, (600, 600))  # noqa: E731
        for args in (["energy", self.cube, "-o", self.path("big.ply")],
                     ["snake", self.cube, "--seeds", "%d,%d" % (a, b), "--spacing", "0.2", "-o", self.path("s.json")]):
            with self.subTest(args=args[0]):
                before = set(os.listdir(self.work))
                p = subprocess.run([CLI] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, preexec_fn=limit,
                                   timeout=60)
                err = p.stderr.decode()
                self.assertEqual(p.returncode, 1, err)
                self.assertRegex(err, "(?i)Cannot write .*File too large.*the existing file, if any, is unchanged")
                self.assertEqual(set(os.listdir(self.work)) - before, set())
        verts, faces = mlhost.grid_cube(80)  # 76800 faces: 10000 smoothing steps take many seconds
        mlhost.write_ply(self.path("big.ply"), verts, faces, binary=True)
        long_run = ["energy", self.path("big.ply"), "--smoothing", "10000", "-q", "-o", self.path("never.ply"),
                    "--json-log"]
        for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
            with self.subTest(signal=sig):
                p = subprocess.Popen([CLI] + long_run, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
                time.sleep(1.0)
                p.send_signal(sig)
                out, err = p.communicate(timeout=30)
                self.assertEqual(p.returncode, -sig, err)
                self.assertIn("stopped by a signal", err.decode())
                self.assertFalse(json.loads(out.decode())["ok"])
        t0 = time.time()
        rc, out, err = run(long_run + ["--timeout", "2"], timeout=60)
        self.assertEqual(rc, 1)
        self.assertLess(time.time() - t0, 20)
        self.assertIn("stopped after --timeout 2 s", err)
        self.assertIn("--timeout", json.loads(out)["error"])
        self.assertEqual([f for f in os.listdir(self.work) if "never" in f], [])
        # what a killed process left (pid 2^22+1 is beyond Linux's pid_max: never a live process)
        stale = self.path(".e.ply.gs-tmp-4194305-1.ply")
        with open(stale, "w") as f:
            f.write("partial")
        self.ok(["energy", self.cube, "-o", self.path("e.ply")])
        self.assertFalse(os.path.exists(stale))

    def test_too_many_seeds_refused_at_once(self):
        """10,000 Pick Points ran for minutes: more than SeedPath::MaxSeeds() (1000) seeds are refused
        before any path search, with a message saying what to do (issue 36)."""
        ply = mlhost.read_ply(ICO)
        pts = [(v["x"], v["y"], v["z"]) for v in ply.vertices][:1500]
        pp = self.path("many.pp")
        with open(pp, "w") as f:
            f.write("<!DOCTYPE PickedPoints>\n<PickedPoints>\n")
            f.writelines('<point x="%r" y="%r" z="%r" active="1" name="%d"/>\n' % (p + (i,)) for i, p in enumerate(pts))
            f.write("</PickedPoints>\n")
        t0 = time.time()
        for cmd in ("path", "snake"):
            with self.subTest(cmd=cmd):
                self.assert_error([cmd, ICO, "--pp", pp, "-o", self.path("never.ply")],
                                  "1500 seed points are given: one path or snake joins at most 1000")
                self.assert_error([cmd, ICO, "--seeds", ",".join(map(str, range(1001))), "-o", self.path("never.ply")],
                                  "1001 seed vertices are given: one path or snake joins at most 1000")
        self.assertLess(time.time() - t0, 20)

    def test_messages_say_what_is_wrong(self):
        """Each hostile input of issue 36 item 8 gets a message that says what is wrong."""
        out = self.path("never.ply")
        head = "ply\nformat ascii 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\n" \
               "element face %s\nproperty list uchar int vertex_indices\nend_header\n"
        files = {
            "neg.ply": (head % ("-5", "1") + "3 0 1 2\n", r"header gives \"-5\" as the number of vertices, which is not a count"),
            "huge.ply": (head % ("3", "99999999999999999999999") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                         r"\"99999999999999999999999\" as the number of faces, which is not a count"),
            "many.ply": (head % ("3", "1000000") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                         "announces 1000000 faces, more than its .* bytes can hold"),
            "short.ply": (head % ("30", "1") + "0 0 0\n", "the file ends before all the vertices and faces its header announces"),
            "neg.off": ("OFF\n-4 -2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", r"\"-4\" as the number of vertices"),
            "negf.off": ("OFF\n3 -2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", r"\"-2\" as the number of faces"),
        }
        for name, (text, why) in files.items():
            with self.subTest(file=name):
                with open(self.path(name), "w") as f:
                    f.write(text)
                self.assert_error(["energy", self.path(name), "-o", out], why)
        # a unit cube moved to 1e7: its vertices merge in float
        far = self.path("far.ply")
        mlhost.write_ply(far, [(x + 1e7, y + 1e7, z + 1e7) for x, y, z in self.cube_verts], self.cube_faces, binary=True)
        self.assert_error(["energy", far, "-o", out], "lies 1e\\+07 from the origin but is only 1.73 across.*single-precision")
        seeds, _ = ico_seeds(2.0)
        js = self.path("never.json")
        self.assert_error(["snake", ICO, "--seed-points", "1e300 0 0; 0 0 0", "-o", js],
                          "too far from the surface to measure")
        self.assert_error(["snake", ICO, "--seeds", seeds, "--gamma", "1e-300", "-o", js],
                          "--gamma 1e-300 is too close to 0")
        self.assert_error(["snake", ICO, "--seeds", "1,2\u00e9", "-o", js], "unexpected character '\u00e9' at position 4")
        with open(self.path("u16.pp"), "wb") as f:
            f.write('<!DOCTYPE PickedPoints>\n<PickedPoints>\n<point x="0" y="0" z="0"/>\n</PickedPoints>\n'.encode("utf-16"))
        self.assert_error(["snake", ICO, "--pp", self.path("u16.pp"), "-o", js], "UTF-16 or UTF-32 text")
        self.assert_error(["path", ICO, "--seeds", "1", "-o", out], "An open snake needs at least 2")
        # zero-area faces: energy and path accept them, the snake says why it does not
        v, f = self.cube_verts, self.cube_faces + [(3, 3, 7)]
        mlhost.write_ply(self.path("rep.ply"), v, f, binary=True)
        a, b = self.cube_index((0.0, 0.0, 0.0)), self.cube_index((1.0, 0.0, 0.0))
        self.ok(["energy", self.path("rep.ply"), "-o", self.path("rep_e.ply")])
        self.ok(["path", self.path("rep.ply"), "--seeds", "%d,%d" % (a, b), "-o", self.path("rep_p.ply")])
        self.assert_error(["snake", self.path("rep.ply"), "--seeds", "%d,%d" % (a, b), "-o", js],
                          "use the same vertex twice. A snake walks from face to face.*the seed path only skip it")

    def test_safe_writes(self):
        """Never the input mesh; a failed run leaves an existing output as it was."""
        size = os.path.getsize(self.cube)
        self.assert_error(["energy", self.cube, "-o", self.cube], "Refusing to write")
        os.symlink(self.cube, self.path("link.ply"))
        self.assert_error(["energy", self.cube, "-o", self.path("link.ply")], "Refusing to write")
        self.assertEqual(os.path.getsize(self.cube), size)
        keep = self.path("keep.json")
        with open(keep, "w") as f:
            f.write('{"precious": true}\n')
        self.assert_error(["snake", self.cube, "--seeds", "0, 99999", "-o", keep], "does not exist")
        self.assertEqual(open(keep).read(), '{"precious": true}\n')
        # A successful run replaces it whole.
        a, b = self.cube_index((0.0, 0.0, 0.0)), self.cube_index((1.0, 0.0, 0.0))
        self.ok(["snake", self.cube, "--seeds", "%d,%d" % (a, b), "-o", keep])
        self.assertIn("samples", json.load(open(keep)))

    # ------------------------------------------------------------------ batch
    def test_batch_20_cases_2_bad(self):
        seeds, _ = ico_seeds(2.0)
        a, b = self.cube_index((0.0, 0.0, 0.0)), self.cube_index((1.0, 1.0, 0.0))
        cases, bad = [], {6, 15}
        for i in range(20):
            if i == 6:
                c = {"command": "snake", "mesh": "missing.ply", "seeds": seeds, "output": "c%d.json" % i}
            elif i == 15:
                c = {"command": "snake", "mesh": ICO, "seeds": [1, 999999], "output": "c%d.json" % i}
            elif i % 3 == 0:
                c = {"command": "energy", "mesh": "cube.ply", "type": ["normal", "curvature", "quadric"][i % 3],
                     "smoothing": i % 4, "output": "c%d.ply" % i}
            elif i % 3 == 1:
                c = {"command": "snake", "mesh": ICO, "seeds": seeds, "alpha": 0.05 + 0.01 * i, "closed": False,
                     "output": "c%d.json" % i}
            else:
                c = {"command": "path", "mesh": "cube.ply", "seeds": "%d, %d" % (a, b), "cost": "feature",
                     "output": "c%d.ply" % i}
            cases.append(c)
        with open(self.path("cases.jsonl"), "w") as f:
            f.write("# twenty cases\n\n")
            for c in cases:
                f.write(json.dumps(c) + "\n")
        t0 = time.time()
        rc, out, err = run(["--batch", self.path("cases.jsonl"), "--json-log"])
        secs = time.time() - t0
        self.assertEqual(rc, 1, out + err)
        lines = [json.loads(l) for l in out.splitlines()]
        results = [l for l in lines if "case" in l]
        summary = [l for l in lines if "batch" in l]
        self.assertEqual(len(results), 20)
        self.assertEqual(sorted(r["case"] for r in results), list(range(1, 21)))
        okays = [r for r in results if r["ok"]]
        errors = [r for r in results if not r["ok"]]
        self.assertEqual(len(okays), 18)
        self.assertEqual(sorted(r["case"] - 1 for r in errors), sorted(bad))
        self.assertEqual(summary, [dict(summary[0], ok=18, errors=2, cases=20)])
        for r in errors:
            self.assertRegex(r["error"], "Cannot (open|read) the mesh|does not exist")
        for i, c in enumerate(cases):
            self.assertEqual(os.path.exists(self.path(c["output"])), i not in bad, c)
        self.assertIn("batch: 20 cases, 18 ok, 2 errors", err)
        print("batch of 20 cases (2 bad): %.2f s wall, %d jobs" % (secs, summary[0]["jobs"]))

    def test_batch_bad_lines(self):
        with open(self.path("cases.jsonl"), "w") as f:
            f.write('{"command": "energy", "mesh": "cube.ply", "output": "ok.ply"}\n')
            f.write('not json\n')
            f.write('{"command": "energy", "mesh": "cube.ply", "nope": 1, "output": "x.ply"}\n')
            f.write('{"mesh": "cube.ply"}\n')
        rc, out, err = run(["--batch", self.path("cases.jsonl"), "-j", "1"])
        self.assertEqual(rc, 1)
        res = {r["line"]: r for r in map(json.loads, out.splitlines())}
        self.assertTrue(res[1]["ok"])
        self.assertIn("not a JSON object", res[2]["error"])
        self.assertIn("no option --nope", res[3]["error"])
        self.assertIn("no \"command\"", res[4]["error"])
        self.assertTrue(os.path.exists(self.path("ok.ply")))
        self.assert_error(["--batch", self.path("none.jsonl")], "Cannot read the batch file")
        self.assert_error(["--batch", self.path("cases.jsonl"), "energy"], "--batch takes", status=2)


    def test_batch_timeout_stops_a_case(self):
        """--timeout: a case that runs too long is stopped and reported; the others finish."""
        verts, faces = mlhost.grid_cube(80)  # 76800 faces: 10000 smoothing steps take many seconds
        mlhost.write_ply(self.path("big.ply"), verts, faces, binary=True)
        with open(self.path("cases.jsonl"), "w") as f:
            f.write('{"command": "energy", "mesh": "big.ply", "smoothing": 10000, "output": "slow.ply"}\n')
            f.write('{"command": "energy", "mesh": "cube.ply", "output": "fast.ply"}\n')
        t0 = time.time()
        rc, out, err = run(["--batch", self.path("cases.jsonl"), "--timeout", "1", "-j", "2"])
        self.assertLess(time.time() - t0, 30)
        self.assertEqual(rc, 1, out + err)
        res = {r["line"]: r for r in map(json.loads, out.splitlines())}
        self.assertIn("longer than --timeout 1 s", res[1]["error"])
        self.assertTrue(res[2]["ok"])
        self.assertFalse(os.path.exists(self.path("slow.ply")))
        self.assertEqual([n for n in os.listdir(self.work) if n.startswith(".")], [], "temporary files left")


    # ------------------------------------------------------------------ cut (issue 34)
    def write_plate_and_square(self):
        return mlhost.plate_and_square(self.work)

    def test_cut_selects_the_inside_and_splits(self):
        mesh, curve, _ = self.write_plate_and_square()
        out = os.path.join(self.work, "cut.ply")
        log, _ = self.ok(["cut", mesh, "--curve", curve, "-o", out, "--json-log"])
        r = json.loads(log)
        self.assertAlmostEqual(r["area_inside"], 25.0, places=9)  # the square's area, exactly
        self.assertAlmostEqual(r["area_outside"], 75.0, places=9)
        self.assertGreater(r["added_vertices"], 0)
        with open(out, "rb") as f:
            header = f.read(2000).split(b"end_header")[0].decode("ascii", "replace")
        self.assertRegex(header, r"element face %d" % (200 + r["added_faces"]))  # plate.ply's 200 faces and the split ones
        self.assertIn("property float quality", header.split("element face")[1])
        log, _ = self.ok(["cut", mesh, "--curve", curve, "--split", "-o", out, "--json-log"])
        r = json.loads(log)
        self.assertEqual(r["inside_faces"] + r["outside_faces"], 200 + r["added_faces"])
        for part in ("cut_inside.ply", "cut_outside.ply"):
            self.assertTrue(os.path.exists(os.path.join(self.work, part)), part)
        # the other side, and cut open
        log, _ = self.ok(["cut", mesh, "--curve", curve, "--side", "larger", "--mode", "cut-open", "-o", out, "--json-log"])
        self.assertAlmostEqual(json.loads(log)["area_inside"], 75.0, places=9)

    def test_cut_refuses_a_curve_of_another_mesh(self):
        mesh, _, curve = self.write_plate_and_square()
        with open(mesh, "rb") as f:
            before = f.read()
        out = os.path.join(self.work, "cut.ply")
        moved = json.loads(json.dumps(curve))
        moved["samples"][1]["position"] = [9, 9, 9]
        bad = os.path.join(self.work, "moved.json")
        with open(bad, "w") as f:
            json.dump(moved, f)
        self.assert_error(["cut", mesh, "--curve", bad, "-o", out], "made on another mesh", outputs=[out])
        far = json.loads(json.dumps(curve))
        far["samples"][2]["face"] = 5000
        with open(bad, "w") as f:
            json.dump(far, f)
        self.assert_error(["cut", mesh, "--curve", bad, "-o", out], "which this mesh does not have", outputs=[out])
        self.assert_error(["cut", mesh, "-o", out], "No curve given", outputs=[out])
        # never over the input mesh or the curve
        self.assert_error(["cut", mesh, "--curve", bad, "-o", out, "--split"], "which this mesh does not have",
                          outputs=[out.replace(".ply", "_inside.ply"), out.replace(".ply", "_outside.ply")])
        with open(mesh, "rb") as f:
            self.assertEqual(f.read(), before)

if __name__ == "__main__":
    unittest.main()
