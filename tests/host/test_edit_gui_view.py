#!/usr/bin/env python3
"""GUI test of the view and the panel while the Geometric Snake tool is active (issue 37), in the
real MeshLab on data/icocube.ply, the panel's state in $GS_SNAKE_PANEL_STATE after every change:
1. The panel docks beside the 3D view and MeshLab's layer dialog, whose Log stays visible (not a
   tab over it): the tool's Log lines give the three boxes; they do not overlap.
2. The status line counts from the state: one seed clicked says "1 seed", Backspace removes it
   and the line says "No seeds".
3. The wheel zooms the view with the tool active (the screenshot differs: fewer mesh pixels after
   zooming out), a middle-button drag pans it, and the tool is still active (a click places a seed).
4. Esc suspends the tool: the panel shows it (and the Log); Esc again resumes.
5. Build: the badge says "not converged" (nothing moves), the status line gives the Build time the
   Log gives, the sample buttons are disabled (no sample selected).
6. The mesh is untouched, so File > Close Project does not ask to save it (no "modified" layer).
"""
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402
from gui import check, wait_for, xdo  # noqa: E402


def test(WORK):
    mesh = g.copy_data("icocube.ply")
    panel = g.panel_state_reader(os.path.join(WORK, "panel.json"))

    with g.MeshLab(mesh, "view") as ml:
        face = g.start_on_front_face(ml, "01_started.png")
        if not face:
            return
        left, right, top, bottom = face
        cx, cy = (left + right) // 2, (top + bottom) // 2

        # ---- 1. where the panel is: beside the view and the layer dialog, the Log visible
        boxes = g.panel_and_layer_dialog(ml)
        if boxes:
            pbox, lbox, shown = boxes
            check(shown == "visible", "MeshLab's layer dialog, with the Log, stays visible (not under a tab)")
            check(not g.overlap(pbox, lbox), "the panel does not cover the layer dialog and its Log")
            check(not g.overlap(pbox, g.VIEW), "the panel does not cover the 3D view")
            img = g.Image(os.path.join(WORK, "01_started.png"))
            lx, ly, lw, lh = lbox  # the Log: the bottom of the layer dialog, white with grey text
            box = (lx + 10, ly + lh * 7 // 10, lx + lw - 10, ly + lh - 10)
            white, dark = img.count((255, 255, 255), box), sum(
                1 for y in range(box[1], box[3]) for x in range(box[0], box[2]) if max(img.px(x, y)) < 200)
            check(white > 0.5 * (box[2] - box[0]) * (box[3] - box[1]) and dark > 50,
                  "the screenshot shows the Log's text there (%d white, %d dark pixels)" % (white, dark))

        # ---- 2. the status line after Backspace removes the only seed
        xdo("mousemove", cx, cy, "click", 1)
        s = panel(lambda s: s["seeds"] == "1 seed")
        check(s.get("status", "").startswith("1 seed:"), "one seed: the status line says \"1 seed\" (%s)" % s.get("status"))
        xdo("key", "BackSpace")
        s = panel(lambda s: s["seeds"] == "0 seeds")
        check(s.get("seeds") == "0 seeds" and s.get("status", "").startswith("No seeds"),
              "Backspace removes it: the panel says 0 seeds and the status line \"No seeds\" (%s)" % s.get("status"))

        # ---- 3. the wheel zooms with the tool active
        count = lambda img: sum(1 for y in range(g.gl_box(img)[1], g.gl_box(img)[3], 3)
                                for x in range(g.gl_box(img)[0], g.gl_box(img)[2], 3) if g.is_mesh(img.px(x, y)))
        before = count(g.Image(g.screenshot("02_before_wheel.png")))
        xdo("mousemove", cx, cy, "click", 4, "click", 4)
        time.sleep(1.0)
        after = count(g.Image(g.screenshot("03_after_wheel.png")))
        check(after < 0.8 * before, "the wheel zooms the view with the tool active (mesh pixels %d -> %d)" % (before, after))
        # the middle button pans (MeshLab's trackball): the mesh moves right with the cursor
        def mesh_x(img):
            x0, y0, x1, y1 = g.gl_box(img)
            xs = [x for y in range(y0, y1, 3) for x in range(x0, x1, 3) if g.is_mesh(img.px(x, y))]
            return sum(xs) / max(1, len(xs))
        xa = mesh_x(g.Image(os.path.join(WORK, "03_after_wheel.png")))
        xdo("mousemove", cx, cy, "mousedown", 2)
        for k in range(1, 9):
            xdo("mousemove", cx + 10 * k, cy)
            time.sleep(0.05)
        xdo("mouseup", 2)
        time.sleep(0.8)
        xb = mesh_x(g.Image(g.screenshot("03b_after_pan.png")))
        check(xb - xa > 40, "a middle-button drag pans the view with the tool active (mesh moved %+.0f px)" % (xb - xa))
        xdo("mousemove", cx + 80, cy, "click", 1)
        check(panel(lambda s: s["seeds"] == "1 seed").get("seeds") == "1 seed",
              "the tool is still active after zooming and panning: a click places a seed")

        # ---- 4. Esc suspends the tool, and the panel shows it
        xdo("key", "Escape")
        s = panel(lambda s: s["suspended"])
        check(s.get("suspended") is True, "Esc: the panel shows the tool is suspended")
        check(bool(wait_for(lambda: "Geometric snake: suspended" in ml.log_text(), 3)), "... and the Log says so")
        g.screenshot("04_suspended.png")
        xdo("key", "Escape")
        check(panel(lambda s: not s["suspended"]).get("suspended") is False, "Esc again: the tool resumes")

        # ---- 5. Build: the badge, the time the Log gives, the sample buttons
        zl, zr, zt, zb = g.front_face_extent(g.Image(g.screenshot("05_zoomed.png")))
        for f in (0.3, 0.5, 0.7):
            xdo("mousemove", int(zl + f * (zr - zl)), (zt + zb) // 2, "click", 1)
            time.sleep(0.3)
        xdo("key", "Return")
        s = panel(lambda s: s["badge"] != "no snake", 5)
        m = wait_for(lambda: re.search(r"built an open snake with \d+ samples in ([0-9.]+) ms", ml.log_text()), 3)
        check(s.get("badge") == "not converged", "after Build the badge says \"not converged\", not \"moving\" (%s)" % s.get("badge"))
        check(bool(m) and ("last: build, %s ms" % m.group(1)) in s.get("status", ""),
              "the status line gives the Build time the Log gives (%s; Log %s ms)" % (s.get("status"), m and m.group(1)))
        check(not s.get("pin") and not s.get("insert") and not s.get("delete"),
              "Pin, Insert and Delete are disabled with no sample selected")
        g.screenshot("06_built.png")

        # ---- 6. the mesh is untouched: File > Close Project closes it without asking to save
        # (MeshLab asks "Project ... modified. Close without saving?" when a layer is modified)
        xdo("mousemove", 30, 10, "click", 1)
        time.sleep(0.8)
        xdo("mousemove", 92, 134, "click", 1)  # Close Project
        time.sleep(1.5)
        prompt = xdo("search", "--name", "^MeshLab$")
        g.screenshot("07_closed.png")
        check(not prompt and ml.p.poll() is None,
              "Close Project asks nothing: starting the tool left the layer unmodified (no save prompt)")


if __name__ == "__main__":
    g.main("edit_gui_view", test)
