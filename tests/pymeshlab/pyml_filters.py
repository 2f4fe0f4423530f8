#!/usr/bin/env python3
"""Runs the Geometric Snake filters through PyMeshLab (run with the virtual environment's python):
loads the plugin with pymeshlab.load_plugin, then each case of a JSON plan on a fresh MeshSet,
and writes what came out (vertex quality, selection, layers, errors) as JSON; the plugin's Log
lines go to stdout (MeshSet.set_verbosity), after a "CASE name" line.

    pyml_filters.py PLUGIN PLAN.json RESULT.json

PLAN: {"mesh": PATH, "cases": [{"name": ..., "filters": [[PYTHON_NAME, {param: value}], ...]}]}; a case's own
"mesh" replaces the plan's.
A filter whose name starts with "!" must fail (PyMeshLabException): its message is kept.
"""
import ctypes
import json
import sys

import pymeshlab

plugin, plan_path, result_path = sys.argv[1:4]
plan = json.load(open(plan_path))
result = {"load": None, "filters": [], "cases": {}}
try:
    pymeshlab.load_plugin(plugin)
    result["load"] = "ok"
except pymeshlab.PyMeshLabException as e:  # the loader's own message (version, scalar type, Qt)
    result["load"] = str(e)
    json.dump(result, open(result_path, "w"))
    sys.exit(3)
# filter_list() names every filter the loaded plugins have (PyMeshLab's names)
result["filters"] = [f for f in pymeshlab.filter_list() if "geometric_snake" in f]

libc = ctypes.CDLL(None)  # PyMeshLab logs through C stdio: flushed before each marker, in order
# Every MeshSet lives to the end: in PyMeshLab 2025.7 a MeshSet destroyed after one of its filters raised
# leaves a dangling log behind, and the next load_new_mesh crashes (std::bad_alloc or SIGSEGV in
# GLLogStream::log), whatever plugin raised (PyMeshLab issue #399; README, "PyMeshLab").
kept = []
for case in plan["cases"]:
    libc.fflush(None)
    print("CASE " + case["name"], flush=True)
    ms = pymeshlab.MeshSet()
    kept.append(ms)
    ms.load_new_mesh(case.get("mesh", plan["mesh"]))
    ms.set_verbosity(True)  # the plugin's Log lines on stdout
    out = {"errors": [], "outputs": []}
    for name, params in case["filters"]:
        must_fail = name.startswith("!")
        try:
            r = ms.apply_filter(name.lstrip("!"), **params)
            out["outputs"].append(r if isinstance(r, dict) else None)
            if must_fail:
                out["errors"].append("succeeded: " + name)
        except pymeshlab.PyMeshLabException as e:
            out["errors"].append(("expected: " if must_fail else "") + str(e))
    ms.set_current_mesh(0)
    m = ms.current_mesh()
    out["vertices"] = m.vertex_number()
    out["quality"] = m.vertex_scalar_array().tolist() if m.has_vertex_scalar() else []
    out["selected"] = [i for i, s in enumerate(m.vertex_selection_array().tolist()) if s]
    out["layers"] = [{"name": ms.mesh(i).label() if hasattr(ms.mesh(i), "label") else str(i),
                      "vertices": ms.mesh(i).vertex_matrix().tolist(),
                      "edges": ms.mesh(i).edge_number()} for i in range(1, ms.mesh_number())]
    result["cases"][case["name"]] = out
libc.fflush(None)
json.dump(result, open(result_path, "w"))
