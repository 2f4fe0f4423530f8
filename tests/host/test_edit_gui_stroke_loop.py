#!/usr/bin/env python3
"""GUI test: one stroke across a part gives a loop round it (issue 33; contour completion).

Run under an X server (CTest: xvfb-run ... test_edit_gui_stroke_loop.py <work folder>). A limb (a
tube of radius 1 standing on a flat body, tests/cli/test_cli_run_end.py's mesh turned to stand
along +y) seen from the side in MeshLab's default view; the session next to the mesh holds five
seeds across the limb's side facing the viewer, from one side of it to the other. L completes
them into a closed snake: its samples go all round the limb (the way back on the hidden side).
R runs it: it ends by itself, converged on the limb's base (the circle of radius 1 in y = 0).
"""
import json
import math
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "cli"))
import gui as g  # noqa: E402
from gui import check, log, run_lines, samples, snakes_of, wait_for, xdo  # noqa: E402
from test_cli_run_end import limb_on_body  # noqa: E402


def test(WORK):
    mesh = os.path.join(WORK, "limb.off")
    h = limb_on_body(mesh, up_y=True)
    tok = open(mesh).read().split()
    nv, nf = int(tok[1]), int(tok[2])
    V = [tuple(map(float, tok[4 + 3 * i:7 + 3 * i])) for i in range(nv)]
    pts = [(math.cos(math.radians(t)), 0.6, math.sin(math.radians(t))) for t in range(10, 171, 40)]
    seeds = [min(range(nv), key=lambda i: sum((V[i][k] - p[k]) ** 2 for k in range(3))) for p in pts]
    json.dump({"format": "geometric-snake-session", "version": 1, "mesh": {"vertices": nv, "faces": nf},
               "seeds": seeds, "snakes": []}, open(mesh + ".snakes.json", "w"))
    auto = os.path.join(WORK, "auto.json")
    with g.MeshLab(mesh, "run") as ml:
        if not check(ml.start_tool(), "the tool starts with the five restored seeds"):
            return
        g.focus_view()
        xdo("key", "l")
        built = wait_for(lambda: g.closed_snake(auto), 30)
        g.screenshot("01_loop.png")
        if not check(bool(built), "L completes the stroke into a closed snake"):
            return
        init = [s["position"] for s in samples(built)[0]["samples"]]
        sectors = {int((math.degrees(math.atan2(p[2], p[0])) + 180) // 45) for p in init}
        check(len(sectors) == 8, "the loop goes all round the limb (%d of 8 sectors round its axis)" % len(sectors))
        check("completed a stroke of 5 seeds into a closed snake" in ml.log_text(), "the Log says what L did")
        xdo("key", "r")
        lines = wait_for(lambda: run_lines(ml.log_text()), 60)
        time.sleep(1.0)
        g.screenshot("02_run.png")
        if not check(bool(lines), "the Run ends by itself"):
            return
        state, ops, comp, wall = lines[0]
        j = wait_for(lambda: (lambda s: s if s and samples(s)[0].get("stats", {}).get("stop") not in (None, "running")
                              else None)(snakes_of(auto)), 10)
        end = [s["position"] for s in samples(j)[0]["samples"]] if j else []
        d = max((abs(math.hypot(p[0], p[2]) - 1) + abs(p[1]) for p in end), default=1e9)
        log("Run %s after %d operations (%.2f s wall); farthest sample %.3f from the base (edge %.3f)" % (
            state, ops, wall, d, h))
        check(state == "converged", "the Run converges (%s)" % state)
        check(d < h, "the snake settles on the limb's base: every sample within an edge length (%.3f < %.3f)" % (d, h))


if __name__ == "__main__":
    g.main("edit_gui_stroke_loop", test)
