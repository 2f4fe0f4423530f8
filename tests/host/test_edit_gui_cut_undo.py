#!/usr/bin/env python3
"""GUI test: the edit tool's Select inside is undone by the tool's own Ctrl+Z, in order with the Run.

Run under an X server (CTest: xvfb-run ... test_edit_gui_cut_undo.py <work folder>): a 10 x 10
plate with a raised square and a square snake on its slopes, restored from the session beside it. R runs the snake; with "Whole
faces only" ticked (the mesh is not changed), "Select inside" selects the faces inside it (drawn
red in the view); Ctrl+Z takes the selection back (no
face drawn selected) and leaves the snake as the Run left it; Ctrl+Y selects them again; two more
Ctrl+Z take back the selection, then the Run (the snake as restored). Then (issue 34) Ctrl+Y
brings the Run back, the exact "Select inside" embeds the snake into the mesh, Ctrl+Z brings the
mesh back as it was (121 vertices, 200 faces, no selection, the snake on its faces), Ctrl+Y cuts
again; "Split into layers" adds two layers and Ctrl+Z removes them; the next Ctrl+Z takes back the
Run (the history from before the cut).
"""
import json
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402
import mlhost  # noqa: E402
from gui import check, curve_state, panel_geometry, run_lines, snakes_of, wait_for  # noqa: E402
from test_edit_gui_cut import selected_pixels  # noqa: E402


def plateau_and_square(folder, n=10):
    """The 10 x 10 plate of unit cells with its square [3, 7]^2 raised by 1, and a closed snake around
    [2.5, 7.5]^2 on its slopes (samples: face, barycentric coordinates and position) with a Balloon
    of 2: its Run converges on the raised square's top (on a flat plate, or with no Balloon, the
    loop collapses and Select inside is refused as it runs over itself)."""
    verts = [(i, j, 1 if 3 <= i <= 7 and 3 <= j <= 7 else 0) for j in range(n + 1) for i in range(n + 1)]
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            faces += [(a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)]
    mesh = os.path.join(folder, "plateau.ply")
    mlhost.write_ply(mesh, verts, faces)

    def loc(x, y):
        i, j = int(x), int(y)
        fx, fy = x - i, y - j
        f = 2 * (j * n + i) + (0 if fx >= fy else 1)
        b = [1 - fx, fx - fy, fy] if fx >= fy else [1 - fy, fx, fy - fx]
        p = [sum(b[k] * verts[faces[f][k]][c] for k in range(3)) for c in range(3)]
        return {"face": f, "bary": b, "position": p}

    return mesh, {"closed": True, "samples": [loc(2.5, 2.5), loc(7.5, 2.5), loc(7.5, 7.5), loc(2.5, 7.5)],
                  "params": {"balloon": 2.0}}


def test(WORK):
    mesh, curve = plateau_and_square(WORK)
    session = {"format": "geometric-snake-session", "version": 1, "mesh": {"vertices": 121, "faces": 200},
               "snakes": [curve], "selected": 0}
    with open(mesh + ".snakes.json", "w") as f:
        json.dump(session, f)
    auto = os.path.join(WORK, "auto.json")
    with g.MeshLab(mesh, "cut_undo") as ml:
        if not check(ml.start_tool(), "the tool starts"):
            return
        time.sleep(2)
        pg = panel_geometry(ml.log_text())
        if not check(bool(pg) and pg[0], "the panel is docked (its Log line)"):
            return
        _, px, py, pw, ph = pg
        # the 3D view as the tool's Log gives it, above MeshLab's info overlay
        view = (g.VIEW[0], g.VIEW[1], g.VIEW[2], g.VIEW[3] - 105) if g.VIEW else (40, 120, 760, 760)
        g.xdo("mousemove", px + 37, py + 678, "click", 1)  # opens the Cut section
        time.sleep(1)
        # Run (R) until it ends by itself or by its time limit; Esc stops it after 20 s
        g.xdo("key", "r")
        if not wait_for(lambda: run_lines(ml.log_text()), 20):
            g.xdo("key", "Escape")
            wait_for(lambda: run_lines(ml.log_text()), 5)
        check(bool(run_lines(ml.log_text())), "the Run ends (%s)" % run_lines(ml.log_text()))
        time.sleep(1)
        ran = curve_state(snakes_of(auto))
        check(ran[0][3] > 0, "the Run made %d operations" % ran[0][3])
        g.xdo("mousemove", px + 100, py + 778, "click", 1)  # Whole faces only
        time.sleep(0.5)
        g.screenshot("00_whole_faces.png")
        g.xdo("mousemove", px + 108, py + 716, "click", 1)  # Select inside
        time.sleep(2)
        m = re.search(r"Selected the inside of snake 1: (\d+) faces .*, whole faces by their centroid\.$", ml.log_text(),
                      re.M)
        check(bool(m) and int(m.group(1)) > 0, "Select inside selects faces (%s)" % (m.group(1) if m else "no Log line"))
        sel = selected_pixels(g.screenshot("01_inside.png"), *view)
        check(sel > 5000, "the inside is drawn selected (%d tinted pixels)" % sel)
        # Ctrl+Z: the selection goes, the snake stays as run
        g.xdo("key", "ctrl+z")
        time.sleep(1.5)
        n = selected_pixels(g.screenshot("02_undone.png"), *view)
        check(n < 100, "Ctrl+Z: no face is drawn selected any more (%d tinted pixels)" % n)
        check(curve_state(snakes_of(auto)) == ran, "Ctrl+Z of the selection leaves the snake as the Run left it")
        # Ctrl+Y: selected again
        g.xdo("key", "ctrl+y")
        time.sleep(1.5)
        n = selected_pixels(g.screenshot("03_redone.png"), *view)
        check(abs(n - sel) < 0.02 * sel, "Ctrl+Y: the same faces are drawn selected again (%d tinted pixels)" % n)
        # Ctrl+Z twice: the selection, then the Run
        g.xdo("key", "ctrl+z")
        time.sleep(1.5)
        g.xdo("key", "ctrl+z")
        time.sleep(1.5)
        n = selected_pixels(g.screenshot("04_run_undone.png"), *view)
        check(n < 100, "no face selected after the second Ctrl+Z (%d tinted pixels)" % n)
        back = curve_state(snakes_of(auto))
        check(back[0][3] == 0 and back[0][1] != ran[0][1],
              "the third Ctrl+Z takes back the Run: the snake as restored (%d operations)" % back[0][3])
        # The exact Select inside adds vertices and faces (issue 34): Ctrl+Z takes the cut back, the
        # mesh as before it and the snake as the Run left it; Ctrl+Y cuts again
        g.xdo("key", "ctrl+y")  # the Run again
        time.sleep(1.5)
        faces_of = lambda st: [[p["face"] for p in c[1]] for c in st]  # noqa: E731
        ran_faces = faces_of(curve_state(snakes_of(auto)))
        g.xdo("mousemove", px + 100, py + 778, "click", 1)  # Whole faces only: off
        time.sleep(0.5)
        g.xdo("mousemove", px + 108, py + 716, "click", 1)  # Select inside, exact
        time.sleep(3)
        g.screenshot("05_cut.png")
        m = re.search(r"Selected the inside of snake 1: \d+ faces .* (\d+) vertices and (\d+) faces added; the session "
                      r"goes on on the cut mesh \(Ctrl\+Z undoes the cut\)\.", ml.log_text())
        check(bool(m) and int(m.group(1)) > 0, "the exact Select inside embeds the snake (%s)"
              % (str(m.groups()) if m else "no Log line"))
        added = (int(m.group(1)), int(m.group(2))) if m else (0, 0)
        check(bool(re.search(r"the cut mesh is not the file plateau\.ply on disk: its session is saved to \S*"
                             r"plateau\.ply\.snakes\.recovered-", ml.log_text())),
              "the Log says where the cut mesh's session is saved (not the uncut file's sidecar)")
        g.xdo("key", "ctrl+z")
        time.sleep(3)
        n = selected_pixels(g.screenshot("06_cut_undone.png"), *view)
        m = re.search(r"Undid the cut \(select inside\): the mesh has (\d+) vertices and (\d+) faces as before it",
                      ml.log_text())
        check(bool(m) and (int(m.group(1)), int(m.group(2))) == (121, 200),
              "Ctrl+Z takes the cut back: 121 vertices and 200 faces (%s)" % (str(m.groups()) if m else "no Log line"))
        check(n < 100, "no face is drawn selected after the cut's undo (%d tinted pixels)" % n)
        time.sleep(1.5)
        check(faces_of(curve_state(snakes_of(auto))) == ran_faces, "the snake is back on the faces the Run left it on")
        g.xdo("key", "ctrl+y")
        time.sleep(3)
        m = re.search(r"Redid the cut \(select inside\): the mesh has (\d+) vertices and (\d+) faces\.", ml.log_text())
        check(bool(m) and (int(m.group(1)), int(m.group(2))) == (121 + added[0], 200 + added[1]),
              "Ctrl+Y cuts again (%s)" % (str(m.groups()) if m else "no Log line"))
        g.xdo("key", "ctrl+z")
        time.sleep(3)
        check(len(re.findall(r"Undid the cut \(select inside\): the mesh has 121 vertices and 200 faces",
                             ml.log_text())) == 2, "Ctrl+Z takes it back again")
        # Split into layers adds two layers; Ctrl+Z removes them
        g.xdo("mousemove", px + 108, py + 747, "click", 1)
        time.sleep(3)
        check(bool(re.search(r"Split along snake 1 into layers \"plateau inside\" \(\d+ faces\) and \"plateau outside\"",
                             ml.log_text())), "Split into layers adds the two layers")
        g.xdo("key", "ctrl+z")
        time.sleep(2)
        g.screenshot("07_split_undone.png")
        check(bool(re.search(r"Undid the split: removed the layers \"plateau inside\", \"plateau outside\"",
                             ml.log_text())), "Ctrl+Z removes the two layers of the split")
        g.xdo("key", "ctrl+z")  # then the Run, as before the cut
        time.sleep(2)
        check(curve_state(snakes_of(auto))[0][3] == 0, "the next Ctrl+Z takes back the Run (the history before the cut)")


if __name__ == "__main__":
    g.main("edit_gui_cut_undo", test)
