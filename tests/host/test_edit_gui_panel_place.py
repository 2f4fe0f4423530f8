#!/usr/bin/env python3
"""GUI test: the Geometric Snake panel comes back where the user last had it (issue 37). MeshLab's
settings (QSettings, group GeometricSnake/Panel, in the test's fresh config folder) say the panel
was last in the right dock area, 360 px wide: started on data/icocube.ply, the tool docks it
there, right of the 3D view and beside MeshLab's layer dialog, whose Log stays visible (not a tab
over it), and about that wide.
"""
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402
from gui import check, log, wait_for  # noqa: E402


def overlap(a, b):
    ax, ay, aw, ah = a
    bx, by, bw, bh = b
    return ax < bx + bw and bx < ax + aw and ay < by + bh and by < ay + ah


def main():
    WORK = g.start("edit_gui_panel_place")
    mesh = g.copy_data("icocube.ply")
    conf = os.path.join(WORK, "config", "VCG")  # MeshLab 2020.09's settings (XDG_CONFIG_HOME)
    os.makedirs(conf)
    with open(os.path.join(conf, "MeshLab_64bit_fp.conf"), "w") as f:
        f.write("[GeometricSnake]\nPanel\\area=2\nPanel\\floating=false\nPanel\\width=360\n")

    ml = g.MeshLab(mesh, "place")
    try:
        if not check(ml.start_tool(), "the tool starts"):
            return g.finish()
        lm = wait_for(lambda: re.search(r"layer dialog \(with the Log\) at (-?\d+),(-?\d+) size (\d+)x(\d+), (\w+)",
                                        ml.log_text()), 5)
        g.screenshot("01_right.png")
        pg = g.panel_geometry(ml.log_text())
        if check(bool(pg) and pg[0] and bool(lm) and g.VIEW, "the tool logs the panel, view and layer dialog boxes"):
            pbox, lbox = pg[1:], tuple(int(lm.group(k)) for k in range(1, 5))
            log("panel %s, view %s, layer dialog %s (%s)" % (pbox, g.VIEW, lbox, lm.group(5)))
            check(pbox[0] >= g.VIEW[0] + g.VIEW[2], "the panel is back in the right dock area, right of the 3D view")
            check(lm.group(5) == "visible" and not overlap(pbox, lbox),
                  "beside the layer dialog, whose Log stays visible (not a tab over it)")
            check(abs(pbox[2] - 360) <= 30, "the panel has the width it had (%d px, was 360)" % pbox[2])
    finally:
        ml.kill()
    return g.finish()


if __name__ == "__main__":
    sys.exit(main())
