#!/usr/bin/env python3
"""GUI test: the tool survives MeshLab ending it (issue 37, observation 2).

Run under an X server (CTest: xvfb-run ... test_edit_gui_lifecycle.py <work folder>). MeshLab
ends the active edit tool whenever a filter starts, even Select All; before, the tool ended
silently and its undo history was lost (Undo greyed out after restarting it). On the cube: the
tool builds a snake (Enter) and runs it (R) to convergence; Filters > Selection > Select All
(its shortcut Ctrl+Shift+A, the menu's own action: its parameter dialog) ends the tool. The Log
must say so (MeshLab ended the tool, the session saved to the sidecar, the undo history kept),
the sidecar must hold the converged snake, the filter applies; the tool started again says the
history is back, and Ctrl+Z returns exactly to the snake as built (the Run taken back), Ctrl+Y
to the converged curve.
"""
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402  (the MeshLab driver, the tool's JSON and Log)
from gui import check, curve_state, log, run_lines, samples, snakes_of, wait_for, xdo  # noqa: E402


def test(WORK):
    mesh = g.copy_data("icocube.ply")
    V, F = g.mesh_ply(mesh)
    h = g.mean_edge(V, F)
    auto = os.path.join(WORK, "auto.json")
    t_start = time.time()
    with g.MeshLab(mesh, "lifecycle") as ml:
        box = g.start_on_front_face(ml, "01_started.png")
        if not box:
            return
        left, right, top, bottom = box
        hpx = (right - left) / 2.0 * h
        built = g.build_from_clicks(auto, left, right, int(top + 2.2 * hpx), min_samples=5)
        if not check(bool(built), "Enter builds a snake"):
            return
        xdo("key", "r")
        if not check(bool(wait_for(lambda: run_lines(ml.log_text()), 20)), "R runs it to its end"):
            return
        ran = wait_for(lambda: (lambda j: j if j and curve_state(j) != curve_state(built) and
                                samples(j)[0]["stats"]["stop"] != "running" else None)(snakes_of(auto)), 10)
        if not check(bool(ran), "the Run moved the snake (%s)" % (
                samples(ran)[0]["stats"]["stop"] if ran else "no JSON")):
            return

        # Filters > Selection > Select All: MeshLab ends the tool as its dialog opens
        xdo("key", "ctrl+shift+a")
        ended = wait_for(lambda: re.search(r"Geometric snake: MeshLab ended the tool on icocube\.ply[^\n]*",
                                           ml.log_text()), 10)
        g.screenshot("02_select_all_dialog.png")
        line = ended.group(0) if ended else ""
        log("Log: " + line)
        check(bool(ended), "the Log says MeshLab ended the tool")
        saved = re.search(r"the session is saved to (icocube\S*\.snakes\.json);", line)
        check(bool(saved), "... and where the session is saved (the sidecar file)")
        sidecar = os.path.join(WORK, saved.group(1) if saved else "icocube.ply.snakes.json")
        m = re.search(r"undo history \((\d+) steps?\) is kept", line)
        check(bool(m) and int(m.group(1)) >= 3, "... and that its undo history is kept (seeds, Build, Run: %s steps)" % (
            m.group(1) if m else "-"))
        xdo("mousemove", 145, 230, "click", 1)  # the dialog's Apply
        check(wait_for(lambda: "Applied filter Select All" in ml.log_text(), 10), "Select All applies")
        time.sleep(0.3)
        xdo("mousemove", 53, 230, "click", 1)  # ... Close
        time.sleep(0.3)
        side = snakes_of(sidecar)
        check(bool(side) and [s["samples"] for s in samples(side)] == [s["samples"] for s in samples(ran)],
              "the sidecar holds the converged snake")

        # the tool again: the history is back, Ctrl+Z takes back the Run made before
        check(ml.start_tool(), "the tool starts again")
        back = wait_for(lambda: re.search(r"the undo history of icocube\.ply is back \((\d+) steps?; Ctrl\+Z undoes the (\w+)\)",
                                          ml.log_text()), 5)
        check(bool(back) and back.group(2) == "run", "the Log says the history is back (%s)" % (
            back.group(0) if back else "no line"))
        check("was dropped" not in ml.log_text(), "nothing was dropped (Select All changes no vertex or face)")
        g.focus_view()
        before = snakes_of(auto)
        xdo("key", "ctrl+z")
        undone = g.changed(auto, before, 10)
        g.screenshot("03_undone.png")
        check(bool(undone) and curve_state(undone) == curve_state(built),
              "Ctrl+Z returns exactly to the snake as built (%s operations, %s samples)" % (
                  samples(undone)[0]["stats"]["operations"] if undone else "-",
                  len(samples(undone)[0]["samples"]) if undone else "-"))
        xdo("key", "ctrl+y")
        redone = g.changed(auto, undone, 10)
        check(bool(redone) and [s["samples"] for s in samples(redone)] == [s["samples"] for s in samples(ran)],
              "Ctrl+Y gives the converged curve again")
        log("test time %.1f s" % (time.time() - t_start))


if __name__ == "__main__":
    g.main("edit_gui_lifecycle", test)
