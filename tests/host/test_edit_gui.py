#!/usr/bin/env python3
"""End-to-end GUI test of the Geometric Snake edit tool in the real MeshLab.

Run under an X server (xvfb-run -a -s "-screen 0 1600x1024x24" python3 test_edit_gui.py ...):
opens data/icocube.ply (cube [-1,1]^3) in MeshLab, starts the tool from the Edit menu,
clicks four seeds two edge lengths below the top edge of the front face, closes them
(Enter), runs the snake (R) and checks from the exported JSON that it converged onto the
cube edge; then drags a sample away and pins it, runs again and checks that the pin held;
checks the snake colour in a screenshot; kills MeshLab (a crash) and checks that the tool
restores the snake from the sidecar file <mesh>.snakes.json when started again.

The tool writes its JSON after every change to $GS_SNAKE_AUTOEXPORT (a hook for this test).
Artifacts (screenshots, JSON, MeshLab log) go to the work folder (first argument).
"""
import json
import math
import os
import re
import signal
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui import (MAGENTA, Image, MeshLab, check, copy_data, dist_cube_edges, dist_polyline, drag,  # noqa: E402
                 edge_on_mesh, front_face_extent, gl_box, log, main, mean_edge, mesh_ply,
                 nearest_cube_edge, sample_near, screenshot, snake_rows, wait_json, xdo)


def test(WORK):
    mesh = copy_data("icocube.ply")
    V, F = mesh_ply(mesh)
    h = mean_edge(V, F)
    auto = os.path.join(WORK, "auto.json")
    sidecar = mesh + ".snakes.json"

    with MeshLab(mesh, "run1", kill=signal.SIGKILL) as ml:  # like a crash: no chance to save at exit
        check(ml.start_tool(), "the tool starts from the Edit menu")
        img = Image(screenshot("01_started.png"))
        time.sleep(1)  # the tool logs where its panel is once the main window has laid it out
        check(bool(re.search(r"panel docked in MeshLab's main window", ml.log_text())) or
              bool(xdo("search", "--name", "^Geometric Snake$")), "the Geometric Snake panel is shown")
        left, right, top, bottom = front_face_extent(img)
        hpx = (right - left) / 2.0 * h  # the front face spans 2 units
        log("front face px: x %d..%d y %d..%d, h = %.4f = %.1f px" % (left, right, top, bottom, h, hpx))

        # seeds: 2.2 edge lengths below the top edge of the front face
        ys = int(top + 2.2 * hpx)
        for f in (0.2, 0.4, 0.6, 0.8):
            xdo("mousemove", int(left + f * (right - left)), ys, "click", 1)
            time.sleep(0.4)
        screenshot("02_seeds.png")
        xdo("key", "Return")
        s = wait_json(auto, lambda s: len(s) == 1 and len(s[0]["samples"]) >= 5, 20)
        check(s is not None and len(s) == 1, "Enter builds the snake from the clicked seeds")
        if not s:
            return
        d0 = [dist_cube_edges(x["position"]) for x in s[0]["samples"][1:-1]]
        log("initial mean distance to the edge: %.2f h" % (sum(d0) / len(d0) / h))
        check(sum(d0) / len(d0) > 1.0 * h, "the initial snake is away from the edge (%.2f h)" % (sum(d0) / len(d0) / h))

        t0 = time.time()
        xdo("key", "r")
        s = wait_json(auto, lambda s: s[0]["stats"]["converged"], 60)
        check(s[0]["stats"]["converged"], "Run: the snake converges (%d operations, %.1f s wall, %.2f ms/op)" % (
            s[0]["stats"]["operations"], time.time() - t0, s[0]["stats"]["ms_per_operation"]))
        pos = [x["position"] for x in s[0]["samples"][1:-1]]
        d = [dist_cube_edges(p) for p in pos]
        mean_d = sum(d) / len(d)
        # The mesh's triangles straddle the exact edge and cut it like a chamfer (up to ~0.45 h
        # deep), so no curve on the mesh gets closer to the exact edge than that: the snake
        # is measured against the edge as the mesh has it (< 0.25 h mean), and against the
        # exact edge (< 0.5 h mean).
        ea, eb = nearest_cube_edge(pos[len(pos) // 2])
        onmesh = edge_on_mesh(V, F, h, ea, eb)
        dm = [dist_polyline(p, onmesh) for p in pos]
        check(sum(dm) / len(dm) < 0.25 * h,
              "converged onto the cube edge as the mesh has it: mean %.3f h, max %.3f h" % (sum(dm) / len(dm) / h, max(dm) / h))
        check(mean_d < 0.5 * h,
              "and near the exact cube edge: mean %.3f h, max %.3f h" % (mean_d / h, max(d) / h))
        img = Image(screenshot("03_converged.png"))
        n = img.count(MAGENTA, gl_box(img))
        check(n > 300, "the snake colour appears in the screenshot (%d px)" % n)

        # drag the middle sample down onto the face and pin it (Edit samples mode is on)
        xm = (left + right) // 2
        ym = snake_rows(img, xm)
        check(bool(ym), "the snake is visible at the middle column")
        if ym:
            x, y = sample_near(img, xm, ym[len(ym) // 2])
            drag(x, y, 0, 3.5 * hpx, 10)  # 3.5 edge lengths down, in 10 mouse moves
            s = wait_json(auto, lambda s: any(x["fixed"] for x in s[0]["samples"]), 10)
            pins = [x for x in s[0]["samples"] if x["fixed"]]
            check(len(pins) == 1, "dragging a sample pins it (%d pinned)" % len(pins))
            if pins:
                pd = dist_cube_edges(pins[0]["position"])
                check(pd > 2.0 * h, "the dragged sample moved away from the edge (%.2f h)" % (pd / h))
                pinpos = pins[0]["position"]
                xdo("key", "r")
                s = wait_json(auto, lambda s: s[0]["stats"]["converged"], 60)
                pins2 = [x for x in s[0]["samples"] if x["fixed"]]
                check(len(pins2) == 1 and math.dist(pins2[0]["position"], pinpos) < 1e-6,
                      "the pin holds exactly while the snake runs again")
                screenshot("04_dragged_pinned.png")
        # undo (Ctrl+Z) changes the snake back
        before = json.load(open(auto))
        xdo("key", "ctrl+z")
        time.sleep(1)
        after = json.load(open(auto))
        check(before != after, "Ctrl+Z undoes the last change")
        xdo("key", "ctrl+y")
        time.sleep(1.5)

        ok = os.path.exists(sidecar)
        check(ok, "the session is autosaved to %s" % os.path.basename(sidecar))
        if ok:
            sc = json.load(open(sidecar))
            check(sc.get("format") == "geometric-snake-session" and len(sc["snakes"]) == 1,
                  "the sidecar file holds the snake")
            check(any(x["fixed"] for x in sc["snakes"][0]["samples"]), "the sidecar file keeps the pin")

    # ---- restart: the tool restores the snake from the sidecar file
    time.sleep(1)
    if os.path.exists(auto):
        os.remove(auto)
    with MeshLab(mesh, "run2") as ml:
        check(ml.start_tool(), "the tool starts again after the crash")
        time.sleep(1.5)
        img = Image(screenshot("05_restored.png"))
        n = img.count(MAGENTA, gl_box(img))
        check(n > 300, "the snake is restored and drawn after restarting MeshLab (%d px)" % n)
        x0, y0, x1, y1 = gl_box(img)
        xdo("mousemove", x0 + 30, (y0 + y1) // 2, "click", 1)  # focus the 3D view (a click away from the snake does nothing)
        time.sleep(0.5)
        xdo("key", "space")  # one step: the auto-export shows the restored snake
        s = wait_json(auto, lambda s: len(s) == 1, 10)
        if s:
            check(any(x["fixed"] for x in s[0]["samples"]), "the restored snake keeps its pin")


if __name__ == "__main__":
    main("edit_gui", test)
