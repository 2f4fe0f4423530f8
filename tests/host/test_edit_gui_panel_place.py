#!/usr/bin/env python3
"""GUI test: the Geometric Snake panel comes back where the user last had it (issue 37). MeshLab's
settings (QSettings, group GeometricSnake/Panel, in the test's fresh config folder) say the panel
was last in the right dock area, 360 px wide: started on data/icocube.ply, the tool docks it
there, right of the 3D view and beside MeshLab's layer dialog, whose Log stays visible (not a tab
over it), and about that wide.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402
from gui import check  # noqa: E402


def test(WORK):
    mesh = g.copy_data("icocube.ply")
    conf = os.path.join(WORK, "config", "VCG")  # MeshLab 2020.09's settings (XDG_CONFIG_HOME)
    os.makedirs(conf)
    with open(os.path.join(conf, "MeshLab_64bit_fp.conf"), "w") as f:
        f.write("[GeometricSnake]\nPanel\\area=2\nPanel\\floating=false\nPanel\\width=360\n")

    with g.MeshLab(mesh, "place") as ml:
        if not check(ml.start_tool(), "the tool starts"):
            return
        boxes = g.panel_and_layer_dialog(ml)
        g.screenshot("01_right.png")
        if boxes:
            pbox, lbox, shown = boxes
            check(pbox[0] >= g.VIEW[0] + g.VIEW[2], "the panel is back in the right dock area, right of the 3D view")
            check(shown == "visible" and not g.overlap(pbox, lbox),
                  "beside the layer dialog, whose Log stays visible (not a tab over it)")
            check(abs(pbox[2] - 360) <= 30, "the panel has the width it had (%d px, was 360)" % pbox[2])


if __name__ == "__main__":
    g.main("edit_gui_panel_place", test)
