#!/usr/bin/env python3
"""GUI test of the edit tool's Cut section (issue 34), in the real MeshLab.

Run under an X server (CTest: xvfb-run ... test_edit_gui_cut.py <work folder>): a flat 10 x 10
plate with a session beside it holding a closed square snake around [2.5, 7.5]^2. The tool starts
and restores the snake; the Cut section (closed at the bottom of the panel) is opened; "Select
inside" embeds the square into the mesh and selects exactly its inside (area 25 of 100: the Log
line, and red selected faces in the view), "Select outside" the others, "Split into layers" adds
the two layers (the Log line), "Cut open" makes the square's edges boundary edges.
"""
import json
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402
import mlhost  # noqa: E402
import subprocess  # noqa: E402
from gui import check, panel_geometry  # noqa: E402


def selected_pixels(png, x, y, w, h):
    """Pixels of MeshLab's selected-face tint (red blended over the grey mesh) in a box."""
    raw = subprocess.run(["convert", png, "-crop", "%dx%d+%d+%d" % (w, h, x, y), "+repage", "-alpha", "off",
                          "-depth", "8", "rgb:-"], capture_output=True).stdout
    return sum(1 for i in range(0, len(raw) - 2, 3) if raw[i] > raw[i + 1] + 50 and raw[i] > raw[i + 2] + 50)


def test(WORK):
    mesh, _, curve = mlhost.plate_and_square(WORK)
    session = {"format": "geometric-snake-session", "version": 1, "mesh": {"vertices": 121, "faces": 200},
               "snakes": [curve], "selected": 0}
    with open(mesh + ".snakes.json", "w") as f:
        json.dump(session, f)
    with g.MeshLab(mesh, "cut", autoexport=False) as ml:
        if not check(ml.start_tool(), "the tool starts"):
            return
        time.sleep(2)
        g.screenshot("01_started.png")
        pg = panel_geometry(ml.log_text())
        if not check(bool(pg) and pg[0], "the panel is docked (its Log line)"):
            return
        _, px, py, pw, ph = pg
        g.log("panel at %d,%d size %dx%d" % (px, py, pw, ph))
        # the Cut section's header, last in the panel (below Parameters), opens it
        g.xdo("mousemove", px + 37, py + 678, "click", 1)
        time.sleep(1)
        g.screenshot("02_cut_open.png")
        vx0, vy0, vx1, _ = g.gl_box(g.Image(os.path.join(WORK, "01_started.png")))
        cx, cy = (vx0 + vx1) // 2, vy0 + 448  # the middle of the 3D view (896 px high)
        inside_box = (cx - 104, cy - 98, 200, 200)  # inside the square snake, in the 3D view
        outside_box = (cx - 259, cy - 248, 90, 90)  # the plate outside it
        # Select inside: the Log line, and the faces inside drawn selected (red)
        g.xdo("mousemove", px + 108, py + 716, "click", 1)
        time.sleep(2)
        g.screenshot("03_inside.png")
        m = re.search(r"Selected the inside of snake 1: (\d+) faces \(area ([0-9.]+) of ([0-9.]+)\)\. The snake was "
                      r"embedded into the mesh: (\d+) vertices and (\d+) faces added", ml.log_text())
        check(bool(m), "Select inside embeds the snake and says what it selected")
        if m:
            check(float(m.group(2)) == 25 and float(m.group(3)) == 100,
                  "exactly the square's inside is selected: %s faces, area %s of %s (%s vertices, %s faces added)"
                  % m.groups())
        shot = os.path.join(WORK, "03_inside.png")
        ri, ro = selected_pixels(shot, *inside_box), selected_pixels(shot, *outside_box)
        check(ri > 15000 and ro < 100, "the inside is drawn selected, the outside not (%d, %d tinted pixels)" % (ri, ro))
        # Select outside: the inverse
        g.xdo("mousemove", px + 302, py + 716, "click", 1)
        time.sleep(2)
        g.screenshot("04_outside.png")
        check(bool(re.search(r"Selected the outside of snake 1: \d+ faces", ml.log_text())), "Select outside says so")
        shot = os.path.join(WORK, "04_outside.png")
        ri, ro = selected_pixels(shot, *inside_box), selected_pixels(shot, *outside_box)
        check(ri < 100 and ro > 5000, "now the outside is drawn selected (%d, %d tinted pixels)" % (ri, ro))
        # Split into layers: two layers, inside and outside, cut exactly (the square has 25 unit cells)
        g.xdo("mousemove", px + 108, py + 747, "click", 1)
        time.sleep(3)
        g.screenshot("05_split.png")
        m = re.search(r"Split along snake 1 into layers \"plate inside\" \((\d+) faces\) and \"plate outside\" "
                      r"\((\d+) faces\)", ml.log_text())
        check(bool(m), "Split into layers adds the inside and outside layers")
        # Cut open: the square's edges become boundary edges of this layer
        g.xdo("mousemove", px + 302, py + 747, "click", 1)
        time.sleep(3)
        g.screenshot("06_cut_open.png")
        m = re.search(r"Cut open along snake 1: its (\d+) vertices on the mesh are on the boundary now \((\d+) vertices",
                      ml.log_text())
        check(bool(m) and int(m.group(2)) >= int(m.group(1)),
              "Cut open gives the curve's vertices a copy on the other side (%s)" % (str(m.groups()) if m else "no Log line"))


if __name__ == "__main__":
    g.main("edit_gui_cut", test)
