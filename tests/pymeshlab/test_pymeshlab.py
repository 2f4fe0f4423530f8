#!/usr/bin/env python3
"""The filter plugin of this source tree in PyMeshLab 2025.7 (PyPI), compared with the same
plugin in this machine's meshlabserver 2020.09 on the same inputs.

    test_pymeshlab.py BUILD_DIR prepare   # scripts/pymeshlab.sh: the venv with the pinned wheel, the
                                          # plugin built for its MeshLab 2025.07 (double)
    test_pymeshlab.py BUILD_DIR filters   # pymeshlab.load_plugin, then every filter from Python:
                                          # energy, seed path, snake (seed vertices, points, .pp
                                          # file), export, an error; the same through meshlabserver

Exit status 0 = pass, 77 = skipped (no MeshLab 2025.07 source: the forky root needs root).
"""
import json
import math
import os
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
TOP = os.path.join(BUILD, "pymeshlab")
PY = os.path.join(TOP, "venv", "bin", "python")
PLUGIN = os.path.join(TOP, "build", "plugins", "libfilter_geometric_snake.so")
WORK = os.path.join(TOP, "work")
MESH = os.path.join(SRC, "data", "icocube.ply")
# PyMeshLab's MeshLab is built in double, meshlabserver 2020.09 (like Debian's 2022.02 and 2025.07)
# in float: the same float input, but the mesh, its normals and the vertex quality in the host's
# scalar type. The per-vertex energy agrees to float rounding (TOL). A snake stops once no sample
# moves by more than its convergence tolerance (params.convergence_tol, in length units) for a few
# operations, so from energies 1e-7 apart two runs reach the same faces after the same number of
# operations but settle a small fraction of that tolerance apart: SNAKE_TOL of it. (Float against
# float, the forky and debian13 tests ask 1e-6 and get 0.)
TOL = 1e-6
SNAKE_TOL = 0.25

PY_NAMES = {mlhost.FILTER_ENERGY: "compute_scalar_by_geometric_snake_feature_energy",
            mlhost.FILTER_SEED_PATH: "compute_selection_by_geometric_snake_seed_path",
            mlhost.FILTER_SNAKE: "compute_geometric_snake_from_seed_vertices",
            mlhost.FILTER_EXPORT: "save_geometric_snake_curves",
            mlhost.FILTER_CUT: "meshing_cut_along_geometric_snake"}


def snake(out, seeds="", points="", pp="", new_layer=True):
    return (mlhost.FILTER_SNAKE, {"Seeds": seeds, "SeedPoints": points, "SeedFile": pp, "Closed": False,
                                  "Alpha": 0.05, "Beta": 0.5, "Gamma": 1.0, "ExternalWeight": 1.0, "Spacing": 1.0,
                                  "MaxOperations": 500, "Method": 0, "UseQuality": False, "OutputFile": out,
                                  "NewLayer": new_layer})


def cases(side):
    """The filter lists of every case; file outputs go to WORK/<side>/."""
    d = os.path.join(WORK, side)
    seeds, h = mlhost.cube_edge_seeds(MESH, 2.5)
    ply = mlhost.read_ply(MESH)
    # the seed vertices as 3D points, 0.3 h off the surface (snapped back onto it)
    pts = [(ply.vertices[i]["x"] + 0.3 * h, ply.vertices[i]["y"], ply.vertices[i]["z"]) for i in seeds]
    pp = os.path.join(WORK, "seeds.pp")
    with open(pp, "w") as f:
        f.write("<!DOCTYPE PickedPoints>\n<PickedPoints>\n")
        for k, p in enumerate(pts):
            f.write(' <point x="%r" y="%r" z="%r" active="1" name="%d"/>\n' % (p[0], p[1], p[2], k))
        f.write("</PickedPoints>\n")
    s = ",".join(map(str, seeds))
    return {
        "energy": [(mlhost.FILTER_ENERGY, {"EnergyType": 0, "SmoothingSteps": 2, "Colorize": True})],
        "seed_path": [(mlhost.FILTER_SEED_PATH, {"Seeds": "%d, %d" % (seeds[0], seeds[-1]), "Closed": False, "Cost": 1,
                                                 "NewLayer": True})],
        "snake_vertices": [snake(os.path.join(d, "vertices.json"), seeds=s)],
        "snake_points": [snake(os.path.join(d, "points.json"),
                               points="; ".join("%r %r %r" % p for p in pts))],
        "snake_pp": [snake(os.path.join(d, "pp.json"), pp=pp)],
        "export": [snake("", seeds=s, new_layer=False),
                   (mlhost.FILTER_EXPORT, {"OutputFile": os.path.join(d, "export.json"), "Which": 0, "NewLayer": False})],
        "error": [("!" + mlhost.FILTER_SNAKE, snake("", seeds="0, 99999999")[1])],
        # the cut filter on its own mesh (CASE_MESH): a plate and a snake file around a square of area 25
        "cut": [(mlhost.FILTER_CUT, {"CurveFile": plate()[1], "Mode": 0, "Side": 0})],
    }


def plate():
    """mlhost.plate_and_square in WORK, made once: (mesh, curve file)."""
    mesh, curve = os.path.join(WORK, "plate.ply"), os.path.join(WORK, "square.json")
    if not os.path.exists(curve):
        mesh, curve, _ = mlhost.plate_and_square(WORK)
    return mesh, curve


def case_mesh(name):
    return plate()[0] if name == "cut" else MESH


def py_value(name, value):
    """PyMeshLab's parameter values: an enum by its label (PyMeshLab's names are MeshLab's, lower case)."""
    return mlhost.ENUMS[name][value] if name in mlhost.ENUMS else value


def run_pymeshlab():
    """Every case through PyMeshLab; returns (result dict, stdout split by case)."""
    os.makedirs(os.path.join(WORK, "pymeshlab"), exist_ok=True)
    plan = {"mesh": MESH, "cases": []}
    for name, filters in cases("pymeshlab").items():
        plan["cases"].append({"name": name, "mesh": case_mesh(name), "filters": [
            [("!" if f.startswith("!") else "") + PY_NAMES[f.lstrip("!")], {k.lower(): py_value(k, v) for k, v in p.items()}]
            for f, p in filters]})
    plan_path, result_path = os.path.join(WORK, "plan.json"), os.path.join(WORK, "pymeshlab.json")
    json.dump(plan, open(plan_path, "w"), indent=1)
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    r = subprocess.run([PY, os.path.join(HERE, "pyml_filters.py"), PLUGIN, plan_path, result_path],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600, env=env)
    logs = {}
    for block in ("\n" + r.stdout).split("\nCASE ")[1:]:
        name, _, text = block.partition("\n")
        logs[name] = text
    result = json.load(open(result_path)) if os.path.exists(result_path) else {}
    if r.returncode != 0:
        print(r.stdout[-3000:])
    check(result.get("load") == "ok", "pymeshlab.load_plugin(%s) loads the plugin: %s" % (PLUGIN, result.get("load")))
    check(r.returncode == 0, "PyMeshLab ran every case (exit %d)" % r.returncode)
    return result, logs


def run_meshlabserver():
    """Every case through meshlabserver 2020.09 (the installed plugins)."""
    d = os.path.join(WORK, "meshlabserver")
    os.makedirs(d, exist_ok=True)
    out, logs = {}, {}
    for name, filters in cases("meshlabserver").items():
        mlx = os.path.join(d, name + ".mlx")
        mlhost.write_mlx(mlx, [(f.lstrip("!"), p) for f, p in filters])
        args = ["-i", case_mesh(name), "-o", os.path.join(d, name + ".ply"), "-m", "vq", "vf"]
        if name == "seed_path":
            args += ["-o", os.path.join(d, name + "_layer.ply"), "-l", "x"]
        rc, logs[name] = mlhost.run_meshlabserver(args + ["-s", mlx])
        out[name] = rc
    return out, logs


def read_json(path):
    return json.load(open(path)) if os.path.exists(path) else None


def same_snake(a, b, what, run=True):
    """The same curve; with `run`, the same run too (length unit, initial curve, operations)."""
    if not check(a is not None and b is not None, "%s: both wrote the snake's JSON" % what):
        return
    unit = b["length_scale"]
    tol = SNAKE_TOL * b["params"]["convergence_tol"] * unit
    if run:
        check(a["length_scale"] == unit and a["initial"] == b["initial"],
              "%s: the same length unit (%g) and the same initial curve" % (what, unit))
    for key in ("samples", "polyline"):
        pa = [c for s in a[key] for c in (s["position"] if isinstance(s, dict) else s)]
        pb = [c for s in b[key] for c in (s["position"] if isinstance(s, dict) else s)]
        check(len(pa) == len(pb) and max_diff(pa, pb) <= tol,
              "%s: same %s: %d vs %d points, max |coordinate difference| %.3g = %.2g units (<= %.2g = %g of the "
              "convergence tolerance)" % (what, key, len(pa) // 3, len(pb) // 3,
                                          max_diff(pa, pb) if len(pa) == len(pb) else float("nan"),
                                          max_diff(pa, pb) / unit if len(pa) == len(pb) else float("nan"), tol, SNAKE_TOL))
    check([s["face"] for s in a["samples"]] == [s["face"] for s in b["samples"]], "%s: same faces under the samples" % what)
    if run:
        check(a["stats"].get("operations") == b["stats"].get("operations") and a["stats"].get("converged"),
              "%s: converged after the same number of operations: %s vs %s"
              % (what, a["stats"].get("operations"), b["stats"].get("operations")))


def filters():
    if os.path.isdir(WORK):
        shutil.rmtree(WORK)
    os.makedirs(WORK)
    py, pylog = run_pymeshlab()
    if py.get("load") != "ok":
        return
    check(sorted(py["filters"]) == sorted(PY_NAMES.values()),
          "PyMeshLab lists the %d filters by their Python names: %s" % (len(PY_NAMES), py["filters"]))
    ms_rc, mslog = run_meshlabserver()
    c = py["cases"]
    for name, rc in ms_rc.items():
        if name != "error":
            check(rc == 0 and not c[name]["errors"], "%s: both ran (meshlabserver exit %d, PyMeshLab errors %s)"
                  % (name, rc, c[name]["errors"]))
    ms = lambda name: mlhost.read_ply(os.path.join(WORK, "meshlabserver", name + ".ply")).vertices

    # energy: the vertex quality, and the raw range the Log reports
    q_ms = [v["quality"] for v in ms("energy")]
    q_py = c["energy"]["quality"]
    check(len(q_py) == len(q_ms) and max_diff(q_py, q_ms) <= TOL,
          "energy: same per-vertex energy: %d vs %d vertices, max |difference| %.3g (<= %g)"
          % (len(q_py), len(q_ms), max_diff(q_py, q_ms) if len(q_py) == len(q_ms) else float("nan"), TOL))
    rng = lambda t: (lambda m: (float(m.group(1)), float(m.group(2))) if m else None)(
        re.search(r"raw range \[([^,\]]+), ([^\]]+)\]", t))
    r_py, r_ms = rng(pylog.get("energy", "")), rng(mslog["energy"])
    check(r_py is not None and r_ms is not None and max_diff(r_py, r_ms) <= TOL * max(1.0, abs(r_ms[1])),
          "energy: same raw range in the Log: PyMeshLab %s, meshlabserver %s" % (r_py, r_ms))

    # seed path: the selected vertices of the mesh and the path layer, in order
    sel_ms = [i for i, v in enumerate(ms("seed_path")) if v["flags"] & mlhost.SELECTED]
    check(len(sel_ms) > 2 and c["seed_path"]["selected"] == sel_ms,
          "seed path: the same %d vertices selected" % len(sel_ms))
    layer_ms = [(v["x"], v["y"], v["z"]) for v in
                mlhost.read_ply(os.path.join(WORK, "meshlabserver", "seed_path_layer.ply")).vertices]
    layers = c["seed_path"]["layers"]
    lp = [x for p in (layers[0]["vertices"] if layers else []) for x in p]
    lm = [x for p in layer_ms for x in p]
    check(len(layers) == 1 and len(lp) == len(lm) and max_diff(lp, lm) <= TOL,
          "seed path: the same path layer (%d vertices, in order)" % (len(lm) // 3))

    # snakes from seed vertices, 3D points and a Pick Points file; the export filter
    for name, f in (("snake_vertices", "vertices.json"), ("snake_points", "points.json"), ("snake_pp", "pp.json")):
        same_snake(read_json(os.path.join(WORK, "pymeshlab", f)), read_json(os.path.join(WORK, "meshlabserver", f)), name)
    a, b = read_json(os.path.join(WORK, "pymeshlab", "export.json")), read_json(os.path.join(WORK, "meshlabserver", "export.json"))
    snakes = lambda j: (j["snakes"] if "snakes" in j else [j]) if j else []
    if check(len(snakes(a)) == 1 and len(snakes(b)) == 1, "export: both wrote the snake kept on the mesh"):
        same_snake(snakes(a)[0], snakes(b)[0], "export", run=False)  # the curve kept, not its run
    check(bool(re.search(r"Exported 1 geometric snake\(s\)", pylog.get("export", ""))),
          "export: PyMeshLab's Log says it exported 1 snake")
    v = read_json(os.path.join(WORK, "pymeshlab", "vertices.json"))
    if v:
        h = mlhost.cube_edge_seeds(MESH, 2.5)[1]
        d = sorted(math.hypot(1.0 - s["position"][0], 1.0 - s["position"][1]) / h for s in v["samples"])
        check(d[int(0.95 * (len(d) - 1))] < 0.6, "PyMeshLab's snake captured the cube edge (95%% of the samples within "
              "%.3f h)" % d[int(0.95 * (len(d) - 1))])

    # the cut: the same vertices (the curve embedded) and the same ones selected inside the square
    cut_ms = ms("cut")
    sel_ms = [i for i, v in enumerate(cut_ms) if v["flags"] & mlhost.SELECTED]
    inside = [i for i, v in enumerate(cut_ms) if 2.5 - 1e-9 <= v["x"] <= 7.5 + 1e-9 and 2.5 - 1e-9 <= v["y"] <= 7.5 + 1e-9]
    check(c["cut"]["vertices"] == len(cut_ms) and c["cut"]["selected"] == sel_ms and sel_ms == inside,
          "cut: the same %d vertices, the same %d selected, exactly those in the square (PyMeshLab: %d, %d)"
          % (len(cut_ms), len(sel_ms), c["cut"]["vertices"], len(c["cut"]["selected"])))

    # a bad seed: PyMeshLabException with the plugin's message, as meshlabserver's Log has it
    err = c["error"]["errors"]
    check(len(err) == 1 and err[0].startswith("expected: ") and "Seed vertex 99999999 does not exist" in err[0],
          "error: PyMeshLab raises the plugin's message: %s" % err)
    check(ms_rc["error"] != 0 and "Seed vertex 99999999 does not exist" in mslog["error"],
          "error: meshlabserver fails with the same message")


def main():
    src = os.path.join(BUILD, "forky", "root", "opt", "gs", "build", "meshlab-src", "ML_VERSION")
    if MODE == "prepare":
        if not os.path.exists(src) and os.geteuid() != 0:
            print("skipped: no MeshLab 2025.07 source (the forky root needs root)")
            return 77
        return subprocess.run(["bash", os.path.join(SRC, "scripts", "pymeshlab.sh"), BUILD]).returncode
    if not os.path.exists(PLUGIN):
        if os.geteuid() != 0:
            print("skipped: no plugin built for PyMeshLab (the forky root needs root)")
            return 77
        check(False, "the plugin for PyMeshLab exists (run the prepare step)")
    elif MODE == "filters":
        filters()
    else:
        raise SystemExit("unknown mode " + MODE)
    return verdict()


if __name__ == "__main__":
    sys.exit(main())
