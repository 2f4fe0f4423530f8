#!/usr/bin/env python3
"""GUI test: a closed snake on the bunny scan Runs in compute time, not redraw time (issue 11).

Run under an X server (CTest: xvfb-run ... test_edit_gui_bunny.py <work folder>). The issue's
case: a closed snake of ~135 samples on bunny00 (75k faces, ../shared/data/meshes) took 462
operations at ~1 ms each but 36 s of wall time, the view redrawn after every operation. Here the
session next to the mesh holds 8 seeds around the bunny's section by the plane at 70 % of its
height along y (about 116 edge lengths round, a sample every 0.86 of them: the session's
parameters, restored with its seeds); MeshLab opens the mesh, the tool starts, Shift+Enter
builds the closed snake, R runs it to its end. The tool's own Log line of the Run gives operations,
compute and wall time: wall <= 2 x compute + 0.5 s (the issue's criterion), the better of two Runs
(Ctrl+Z between them: the machine is shared).
"""
import json
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402  (the MeshLab driver, the tool's JSON and Log)
from gui import check, log, run_lines, samples, snakes_of, wait_for, xdo  # noqa: E402

MESHES = os.path.join(g.DATA, "..", "..", "shared", "data", "meshes")


def read_off(path):
    tok = open(path).read().split()
    nv, nf = int(tok[1]), int(tok[2])
    V = [tuple(map(float, tok[4 + 3 * i:7 + 3 * i])) for i in range(nv)]
    return V, nf


def section_seeds(V, axis, frac, h, n=8):
    """n vertices evenly round the mesh's section by the plane at `frac` of its extent along `axis`."""
    lo, hi = min(v[axis] for v in V), max(v[axis] for v in V)
    c = lo + frac * (hi - lo)
    ring = [i for i, v in enumerate(V) if abs(v[axis] - c) < h / 2]
    u, w = (axis + 1) % 3, (axis + 2) % 3
    cu, cw = sum(V[i][u] for i in ring) / len(ring), sum(V[i][w] for i in ring) / len(ring)
    ring.sort(key=lambda i: math.atan2(V[i][w] - cw, V[i][u] - cu))
    return [ring[k * len(ring) // n] for k in range(n)]


def test(WORK):
    src = os.path.join(MESHES, "bunny00.off")
    if not check(os.path.exists(src), "the bunny scan is there (%s)" % os.path.normpath(src)):
        return
    mesh = os.path.join(WORK, "bunny00.off")
    with open(src) as f, open(mesh, "w") as o:
        o.write(f.read())
    V, nf = read_off(mesh)
    h = 0.00889  # bunny00's mean edge length
    seeds = section_seeds(V, 1, 0.7, h)
    json.dump({"format": "geometric-snake-session", "version": 1, "mesh": {"vertices": len(V), "faces": nf},
               "seeds": seeds, "snakes": [], "params": {"spacing": 0.86}},  # ~135 samples round
              open(mesh + ".snakes.json", "w"))
    auto = os.path.join(WORK, "auto.json")

    with g.MeshLab(mesh, "run") as ml:
        if not check(ml.start_tool(), "the tool starts on the bunny with the restored seeds"):
            return
        time.sleep(1.5)
        xdo("mousemove", 400, 950, "click", 1)  # focus the 3D view, away from the mesh
        time.sleep(0.3)
        xdo("key", "Escape")  # (a click may start nothing: Esc twice suspends and resumes the tool)
        time.sleep(0.3)
        xdo("key", "Escape")
        time.sleep(0.3)
        xdo("key", "shift+Return")
        built = wait_for(lambda: (lambda j: j if j and samples(j) and samples(j)[0]["closed"] else None)(
            snakes_of(auto)), 30)
        if not check(bool(built), "Shift+Enter builds a closed snake from the seeds"):
            return
        n = len(samples(built)[0]["samples"])
        check(120 <= n <= 150, "the closed snake has about the issue's 135 samples, at the session's spacing (%d)" % n)
        best = None
        for attempt in range(2):
            nlines = len(run_lines(ml.log_text()))
            xdo("key", "r")
            lines = wait_for(lambda: run_lines(ml.log_text())[nlines:], 180)
            if not check(bool(lines), "Run %d ends with its Log line" % (attempt + 1)):
                break
            state, ops, comp, wall = lines[0]
            log("Run %d: %s after %d operations of %d samples: compute %.3f s, wall %.3f s (%.2f ms per operation)" % (
                attempt + 1, state, ops, n, comp, wall, 1000 * comp / max(ops, 1)))
            if best is None or wall - 2 * comp < best[3] - 2 * best[2]:
                best = lines[0]
            time.sleep(0.5)
            xdo("key", "ctrl+z")  # the whole Run is one undo step: back to the snake as built
            time.sleep(1.0)
        g.screenshot("01_bunny.png")
        if best:
            state, ops, comp, wall = best
            check(ops >= 100, "a long Run (%d operations)" % ops)
            check(wall <= 2 * comp + 0.5, "wall time %.3f s <= 2 x compute %.3f s + 0.5 s" % (wall, comp))


if __name__ == "__main__":
    g.main("edit_gui_bunny", test)
