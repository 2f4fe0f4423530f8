#!/usr/bin/env python3
"""The plugins built from this source tree in a real Debian system of another release,
compared with the same plugins in this machine's MeshLab 2020.09. RELEASE (default trixie):
trixie = Debian 13, MeshLab 2022.02 (build/debian13/root); forky = Debian 14, MeshLab 2025.07
(build/forky/root).

    test_debian13.py BUILD_DIR prepare [RELEASE]  # scripts/debian_root.sh: the cached root, the
                                                  # plugins built and installed in it
    test_debian13.py BUILD_DIR filters [RELEASE]  # that MeshLab's library (gs_meshlab_check) loads
                                                  # and lists the plugins and applies the filters (the
                                                  # cut too); the results equal MeshLab 2020.09's
                                                  # (meshlabserver)
    test_debian13.py BUILD_DIR gui [RELEASE]      # that MeshLab's GUI loads every plugin, the edit
                                                  # tool starts, its panel docks beside the view and the
                                                  # Log, clicks build and run a snake, the wheel zooms

Exit status 0 = pass, 77 = skipped (not root: chroot needs it).
"""
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(SRC, "tests", "host"))
import mlhost  # noqa: E402
from checks import check, max_diff, verdict  # noqa: E402

BUILD = os.path.abspath(sys.argv[1])
MODE = sys.argv[2]
RELEASE = sys.argv[3] if len(sys.argv) > 3 else "trixie"
# release: (folder in the build tree, Debian, MeshLab, the GUI test clicks a snake)
NAME, DEBIAN, VERSION, CLICKS = {"trixie": ("debian13", "Debian 13", "2022.02", True),
                                 "forky": ("forky", "Debian forky", "2025.07", True)}[RELEASE]
ROOT = os.path.join(BUILD, NAME, "root")
SCRIPT = os.path.join(SRC, "scripts", "debian_root.sh")
PLUGIN_DIR = "/usr/lib/x86_64-linux-gnu/meshlab/plugins"  # Debian's MeshLab plugin folder
WORK = os.path.join(BUILD, NAME, "work")
ICOCUBE = "icocube.ply"
TOL = 1e-6

ENERGY = (mlhost.FILTER_ENERGY, {"EnergyType": 0, "SmoothingSteps": 2, "Colorize": True})


def seed_path(seeds):
    """The feature-cost path between the first and last seed, as a new layer (and the vertex selection)."""
    s = seeds.split(",")
    return (mlhost.FILTER_SEED_PATH, {"Seeds": "%s, %s" % (s[0], s[-1]), "Closed": False, "Cost": 1, "NewLayer": True})


def snake(seeds, out):
    return (mlhost.FILTER_SNAKE, {"Seeds": seeds, "Closed": False, "Alpha": 0.05, "Beta": 0.5, "Gamma": 1.0,
                                  "ExternalWeight": 1.0, "Spacing": 1.0, "MaxOperations": 500, "Method": 0,
                                  "UseQuality": False, "OutputFile": out, "NewLayer": True})


def xvfb_run(screen):
    """xvfb-run inside the root on a display number free on the host: X servers listen on
    abstract sockets, shared with the host, while the root's xvfb-run -a only sees its own /tmp."""
    for n in random.sample(range(200, 1000), 800):
        if not os.path.exists("/tmp/.X%d-lock" % n) and not os.path.exists("/tmp/.X11-unix/X%d" % n):
            # Our own auth file (-f): when xvfb-run fails to remove its own temporary folder it
            # exits before stopping its Xvfb (as mlhost.meshlabserver_cmd notes).
            return ["xvfb-run", "-n", str(n), "-f", "/tmp/gs-xauth-%d" % n, "-s", "-screen 0 " + screen]
    raise RuntimeError("no free X display number")


def in_root(*cmd, timeout=900):
    r = subprocess.run(["bash", SCRIPT, RELEASE, BUILD, "--run"] + list(cmd), capture_output=True, text=True, timeout=timeout)
    return r.returncode, r.stdout + r.stderr


def cli_args(filters):
    """gs_meshlab_check's "FILTER Name=Value ... -- FILTER ..." arguments."""
    args = []
    for name, params in filters:
        if args:
            args.append("--")
        args.append(name)
        for k, v in params.items():
            args.append("%s=%s" % (k, ("true" if v else "false") if isinstance(v, bool) else v))
    return args


def points(j, key):
    return [c for s in j[key] for c in (s["position"] if isinstance(s, dict) else s)]


def run_root(seeds):
    """The filters through the root's MeshLab library; returns (log, quality, snake json)."""
    out = "/opt/gs/out"
    shutil.rmtree(ROOT + out, ignore_errors=True)
    os.makedirs(ROOT + out)
    args = cli_args([ENERGY, snake(seeds, out + "/snake.json"), seed_path(seeds),
                     ("!" + mlhost.FILTER_SNAKE, {"Seeds": "0, 99999999"})])
    # MeshLab's own libraries on the library path, as the meshlab program's RUNPATH has them: since
    # 2023 some of MeshLab's plugins (edit_align, edit_pickpoints) need libmeshlab-common-gui.so
    # and have no RUNPATH of their own, they count on the program having loaded it.
    rc, text = in_root(*xvfb_run("640x480x24"), "env", "LD_LIBRARY_PATH=" + os.path.dirname(PLUGIN_DIR),
                       "/opt/gs/build/tests/meshlab2022/gs_meshlab_check",
                       PLUGIN_DIR, "/opt/gs/src/data/" + ICOCUBE, out, *args)
    print(text)
    check(rc == 0, "gs_meshlab_check (MeshLab %s's PluginManager, I/O plugins and applyFilter) passed" % VERSION)
    check(("MeshLab %s (single precision)" % VERSION) in text, "the root's MeshLab library is %s, float" % VERSION)
    for name in (mlhost.FILTER_ENERGY, mlhost.FILTER_SEED_PATH, mlhost.FILTER_SNAKE, mlhost.FILTER_EXPORT, mlhost.FILTER_CUT):
        check(re.search(r'^FILTER "%s" python=\w+ ' % re.escape(name), text, re.M) is not None,
              "MeshLab %s lists the filter '%s' with a PyMeshLab name" % (VERSION, name))
    quality = [float(x) for x in open(ROOT + out + "/quality_1.txt").read().split()] \
        if os.path.exists(ROOT + out + "/quality_1.txt") else []
    j = json.load(open(ROOT + out + "/snake.json")) if os.path.exists(ROOT + out + "/snake.json") else None
    # the seed path (run 3): its selected vertices and its layer
    m = re.search(r"^SELECTED 3:(.*)$", text, re.M)
    layer = ROOT + out + "/layer_3_1.txt"
    path = {"selected": [int(x) for x in m.group(1).split()] if m else None,
            "layer": [float(x) for x in open(layer).read().split()] if os.path.exists(layer) else []}
    return text, quality, j, path


def run_2020(seeds):
    """The same filters through this machine's meshlabserver 2020.09 (the installed plugins)."""
    os.makedirs(WORK, exist_ok=True)
    mesh = os.path.join(SRC, "data", ICOCUBE)
    energy_mlx, snake_mlx = os.path.join(WORK, "energy.mlx"), os.path.join(WORK, "snake.mlx")
    energy_ply, snake_json = os.path.join(WORK, "energy_2020.ply"), os.path.join(WORK, "snake_2020.json")
    for f in (energy_ply, snake_json):
        if os.path.exists(f):
            os.remove(f)
    mlhost.write_mlx(energy_mlx, [ENERGY])
    rc1, log1 = mlhost.run_meshlabserver(["-i", mesh, "-o", energy_ply, "-m", "vq", "-s", energy_mlx])
    mlhost.write_mlx(snake_mlx, [snake(seeds, snake_json)])
    rc2, log2 = mlhost.run_meshlabserver(["-i", mesh, "-s", snake_mlx])
    path_mlx, path_ply, layer_ply = (os.path.join(WORK, f) for f in ("path.mlx", "path_2020.ply", "path_layer_2020.ply"))
    mlhost.write_mlx(path_mlx, [seed_path(seeds)])
    rc3, log3 = mlhost.run_meshlabserver(["-i", mesh, "-o", path_ply, "-m", "vf", "-o", layer_ply, "-l", "x", "-s", path_mlx])
    check(rc1 == 0 and rc2 == 0 and rc3 == 0, "meshlabserver 2020.09 ran the same filters")
    quality = [v["quality"] for v in mlhost.read_ply(energy_ply).vertices] if os.path.exists(energy_ply) else []
    j = json.load(open(snake_json)) if os.path.exists(snake_json) else None
    path = {"selected": [i for i, v in enumerate(mlhost.read_ply(path_ply).vertices) if v["flags"] & mlhost.SELECTED]
            if os.path.exists(path_ply) else None,
            "layer": [c for v in mlhost.read_ply(layer_ply).vertices for c in (v["x"], v["y"], v["z"])]
            if os.path.exists(layer_ply) else []}
    return log1 + log2 + log3, quality, j, path


def cut_root(mesh, curve, moved):
    """The cut filter through the root's MeshLab library on mlhost.plate_and_square's plate:
    select inside, split into two layers, and a curve of another mesh refused."""
    rc, text = in_root(*xvfb_run("640x480x24"), "env", "LD_LIBRARY_PATH=" + os.path.dirname(PLUGIN_DIR),
                       "/opt/gs/build/tests/meshlab2022/gs_meshlab_check", PLUGIN_DIR, mesh, os.path.dirname(mesh),
                       *cli_args([(mlhost.FILTER_CUT, {"CurveFile": curve}),
                                  (mlhost.FILTER_CUT, {"CurveFile": curve, "Split": True}),
                                  ("!" + mlhost.FILTER_CUT, {"CurveFile": moved})]))
    print(text)
    check(rc == 0, "gs_meshlab_check ran the cut filter in MeshLab %s" % VERSION)
    return text


def cut_2020(mesh, curve):
    """The same select-inside cut through meshlabserver 2020.09: (vertices, selected vertices,
    faces, area of the faces it marks inside (face quality 1))."""
    mlx, out = os.path.join(WORK, "cut.mlx"), os.path.join(WORK, "cut_2020.ply")
    if os.path.exists(out):
        os.remove(out)
    mlhost.write_mlx(mlx, [(mlhost.FILTER_CUT, {"CurveFile": curve})])
    rc, log = mlhost.run_meshlabserver(["-i", mesh, "-o", out, "-m", "vf", "fq", "-s", mlx])
    check(rc == 0 and os.path.exists(out), "meshlabserver 2020.09 ran the cut filter")
    if not os.path.exists(out):
        return None
    ply = mlhost.read_ply(out)
    area = mlhost.inside_area(ply)
    return (len(ply.vertices), [i for i, v in enumerate(ply.vertices) if v["flags"] & mlhost.SELECTED],
            len(ply.faces), area)


def cut():
    """Issue 34 in this MeshLab: the cut filter selects the inside of a square loop (area 25
    exactly), splits the plate into two layers, refuses a curve of another mesh; the selection
    equals MeshLab 2020.09's."""
    out = "/opt/gs/cut"
    shutil.rmtree(ROOT + out, ignore_errors=True)
    os.makedirs(ROOT + out)
    _, _, data = mlhost.plate_and_square(ROOT + out)
    data["samples"][1]["position"] = [9, 9, 9]  # a sample off the plate: "made on another mesh"
    with open(ROOT + out + "/moved.json", "w") as f:
        json.dump(data, f)
    text = cut_root(out + "/plate.ply", out + "/square.json", out + "/moved.json")
    m = re.search(r"^RESULT 1 layers=1 vertices=(\d+)", text, re.M)
    sel = re.search(r"^SELECTED 1:(.*)$", text, re.M)
    faces = re.search(r"^FACES 1: faces=(\d+) selected=(\d+) selected_area=(\S+)", text, re.M)
    check(re.search(r"Cut \(select\) along a closed snake", text) is not None, VERSION + ": the cut filter logs its select")
    check(faces is not None and abs(float(faces.group(3)) - 25.0) < 1e-5,
          VERSION + ": select inside selects the square's inside, area %s (25 exactly)" % (faces.group(3) if faces else None))
    layers = re.findall(r'^LAYER 2 \d+ "([^"]*)" vertices=(\d+) edges=\d+ faces=(\d+)', text, re.M)
    check(len(layers) == 2 and all(int(f) > 0 for _, _, f in layers),
          VERSION + ": split adds two layers with faces: %s" % (layers,))
    check(re.search(r"^ERROR .*made on another mesh", text, re.M) is not None,
          VERSION + ": a curve of another mesh is refused (\"made on another mesh\")")
    r20 = cut_2020(ROOT + out + "/plate.ply", ROOT + out + "/square.json")
    if r20 and m and sel and faces:
        mine = (int(m.group(1)), [int(x) for x in sel.group(1).split()], int(faces.group(1)))
        check(mine == r20[:3], "the same cut as 2020.09: %d vertices, %d selected, %d faces (2020.09: %d, %d, %d)"
              % (mine[0], len(mine[1]), mine[2], r20[0], len(r20[1]), r20[2]))
        check(abs(r20[3] - float(faces.group(3))) < 1e-5, "the same inside area as 2020.09 (%.6f)" % r20[3])


def raw_range(log):
    m = re.search(r"raw range \[([^,\]]+), ([^\]]+)\]", log)
    return (float(m.group(1)), float(m.group(2))) if m else None


def filters():
    seeds, h = mlhost.cube_edge_seeds(os.path.join(SRC, "data", ICOCUBE), 2.5)
    seeds = ",".join(map(str, seeds))
    log_root, q_root, j_root, path_root = run_root(seeds)
    log20, q20, j20, path20 = run_2020(seeds)

    # The seed path: the same vertices selected, the same path layer in order.
    sel = path_root["selected"]
    check(sel is not None and len(sel) > 2 and sel == path20["selected"],
          "same seed path: %s selected vertices %s, 2020.09 %s" % (VERSION, sel, path20["selected"]))
    a, b = path_root["layer"], path20["layer"]
    check(len(a) > 6 and len(a) == len(b) and max_diff(a, b) <= TOL,
          "same seed path layer: %d vs %d vertices in order, max |coordinate difference| %.3g (<= %g)"
          % (len(a) // 3, len(b) // 3, max_diff(a, b) if len(a) == len(b) else float("nan"), TOL))

    # The energy filter writes the vertex quality, over [0,1], in both.
    check(len(q_root) > 0 and min(q_root) == 0.0 and max(q_root) == 1.0,
          VERSION + ": the energy filter wrote the vertex quality, range [%s, %s]" % (min(q_root, default=None), max(q_root, default=None)))
    r_root, r20 = raw_range(log_root), raw_range(log20)
    check(r_root is not None and r_root == r20, "same raw energy range: %s %s, 2020.09 %s" % (VERSION, r_root, r20))
    check(len(q_root) == len(q20) and max_diff(q_root, q20) <= TOL,
          "same per-vertex energy: %d vs %d vertices, max |difference| %.3g (<= %g)"
          % (len(q_root), len(q20), max_diff(q_root, q20) if len(q_root) == len(q20) else float("nan"), TOL))

    # The snake captures the cube edge x = y = 1, writes the JSON contract, same curve as 2020.09.
    if not check(j_root is not None and j20 is not None, "both wrote the snake's JSON"):
        return
    for key in ("closed", "initial", "samples", "polyline", "stats"):
        check(key in j_root, "%s JSON has '%s'" % (VERSION, key))
    check(all(set(s) == {"face", "bary", "position", "fixed"} for s in j_root["samples"]), VERSION + " JSON samples: face, bary, position, fixed")
    check(j_root["stats"].get("converged") is True, VERSION + ": the snake converged")
    d = sorted(math.hypot(1.0 - s["position"][0], 1.0 - s["position"][1]) / h for s in j_root["samples"])
    check(d and d[int(0.95 * (len(d) - 1))] < 0.6,
          VERSION + ": the snake captured the cube edge (95%% of the samples within %.3f h, < 0.6 h)" % (d[int(0.95 * (len(d) - 1))] if d else -1))
    for key in ("samples", "polyline"):
        a, b = points(j_root, key), points(j20, key)
        check(len(a) == len(b) and max_diff(a, b) <= TOL,
              "same snake %s: %d vs %d, max |coordinate difference| %.3g (<= %g)"
              % (key, len(a) // 3, len(b) // 3, max_diff(a, b) if len(a) == len(b) else float("nan"), TOL))
    check([s["face"] for s in j_root["samples"]] == [s["face"] for s in j20["samples"]], "same faces under the samples")
    check(j_root["stats"].get("operations") == j20["stats"].get("operations"),
          "same number of operations: %s vs %s" % (j_root["stats"].get("operations"), j20["stats"].get("operations")))


def gui():
    rc, text = in_root(*xvfb_run("1600x1024x24"), "python3", "/opt/gs/src/tests/debian13/gui_in_root.py",
                       "/opt/gs/src/data/" + ICOCUBE, "/opt/gs/gui", VERSION, *(["--clicks"] if CLICKS else []))
    print(text)
    check(rc == 0, "MeshLab %s's GUI loaded the plugins and started the edit tool%s"
          % (VERSION, ", which built and ran a snake from clicks" if CLICKS else ""))


def main():
    if os.geteuid() != 0:
        print("skipped: the %s root needs root (debootstrap, chroot)" % DEBIAN)
        return 77
    if MODE == "prepare":
        return subprocess.run(["bash", SCRIPT, RELEASE, BUILD]).returncode
    if not os.path.exists(os.path.join(ROOT, ".gs-ready")):
        check(False, "the %s root exists (run the prepare step)" % DEBIAN)
    elif MODE == "filters":
        filters()
        cut()
    elif MODE == "gui":
        gui()
    else:
        raise SystemExit("unknown mode " + MODE)
    return verdict()


if __name__ == "__main__":
    sys.exit(main())
