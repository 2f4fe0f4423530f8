#!/usr/bin/env python3
"""GUI test of the edit tool with an unreadable sidecar (issue 8), in the real MeshLab.

Run under an X server (CTest: xvfb-run ... test_edit_gui_sidecar.py <work folder>): a truncated
<mesh>.snakes.json lies next to data/icocube.ply. MeshLab opens the mesh, the Geometric Snake
tool starts, a seed is placed, the tool ends. The truncated sidecar must be unchanged byte for
byte, its .bak untouched, the session must be in <mesh>.snakes.recovered-<time>.json, and the
Log (MeshLab's stdout echo) and the panel's status line (red pixels in the screenshot) must say so.
"""
import glob
import json
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402  (the MeshLab driver, screenshots, pixel counts)
from gui import check, panel_geometry, read_bytes, red_pixels  # noqa: E402


def test(WORK):
    mesh = g.copy_data("icocube.ply")
    sidecar = mesh + ".snakes.json"
    # a session file cut in the middle, as a crash of another program or a full disk leaves it
    session = {"format": "geometric-snake-session", "version": 1, "mesh": {"vertices": 1, "faces": 1},
               "snakes": [{"closed": False, "samples": [{"face": i, "bary": [0.2, 0.3, 0.5], "fixed": False}
                                                        for i in range(50)]}]}
    text = json.dumps(session, indent=1)
    with open(sidecar, "w") as f:
        f.write(text[:len(text) // 2])
    with open(sidecar + ".bak", "w") as f:
        f.write("an older backup the user keeps\n")
    before, bak_before = read_bytes(sidecar), read_bytes(sidecar + ".bak")

    with g.MeshLab(mesh, "run", autoexport=False) as ml:
        if not check(ml.start_tool(), "the tool starts"):
            return
        time.sleep(1)
        g.screenshot("01_started.png")
        check(read_bytes(sidecar) == before, "starting the tool leaves the truncated sidecar as it was")
        # the Log (MeshLab echoes it as "LOG: <level> <text>"): a warning that names the kept file
        # and the recovery file
        m = re.search(r"LOG: 1 Geometric snake: (.*kept unchanged; this session is saved to (\S+)\.)\n", ml.log_text())
        check(bool(m), "the Log warns that the sidecar is kept and names the recovery file (%s)" % (
            m.group(1) if m else "no such line"))
        if m:
            check(re.fullmatch(re.escape(mesh) + r"\.snakes\.recovered-\d{8}-\d{6}(-\d+)?\.json", m.group(2)) is not None,
                  "the Log names <mesh>.snakes.recovered-<time>.json (%s)" % os.path.basename(m.group(2)))
        # the status line at the top of the panel shows the warning in red (error style)
        pg = panel_geometry(ml.log_text())
        if check(bool(pg) and pg[0], "the panel is docked (its Log line)"):
            _, px, py, pw, ph = pg
            reds = red_pixels(os.path.join(WORK, "01_started.png"), px, py + 20, pw, 120)
            check(reds > 40, "the panel's status line shows the warning in red (%d red pixels)" % reds)

        x0, y0, x1, y1 = g.gl_box(g.Image(os.path.join(WORK, "01_started.png")))
        g.xdo("mousemove", (x0 + x1) // 2, (y0 + y1) // 2, "click", 1)  # a seed on the cube (middle of the 3D view)
        time.sleep(2)
        g.screenshot("02_seed.png")
        g.xdo("mousemove", 70, 10, "click", 1)  # the same menu entry again ends the tool (it saves)
        time.sleep(1)
        g.xdo("mousemove", 141, 84, "click", 1)
        time.sleep(3)
        g.screenshot("03_ended.png")

    check(read_bytes(sidecar) == before, "the truncated sidecar is unchanged byte for byte")
    check(read_bytes(sidecar + ".bak") == bak_before, "the old .bak file is not replaced")
    rec = sorted(glob.glob(mesh + ".snakes.recovered-*.json"))
    if check(len(rec) == 1, "one recovery file next to the mesh (%s)" % [os.path.basename(r) for r in rec]):
        j = json.load(open(rec[0]))
        check(j.get("format") == "geometric-snake-session", "the recovery file is a session")
        check(len(j.get("seeds", [])) == 1, "it holds the placed seed (%d seeds)" % len(j.get("seeds", [])))


if __name__ == "__main__":
    g.main("edit_gui_sidecar", test)
