#!/usr/bin/env python3
"""GUI tests of the Geometric Snake edit tool's editing, snakes, exports and layers in the real MeshLab.

Run under an X server (xvfb-run -a -s "-screen 0 1600x1024x24" python3 test_edit_gui_edit.py WORK),
on data/icocube.ply (cube [-1,1]^3), the tool's JSON after every change in $GS_SNAKE_AUTOEXPORT:
1. Keys: a clicked sample, then I inserts a sample after it (the others stay where they were),
   P pins it, P unpins it, Delete removes it; Ctrl+Z x3 and Ctrl+Y x2 walk that history back and
   forth exactly.
2. Several snakes: the first snake Run to convergence; New, seeds and Enter build a second one
   (the first keeps "converged"); choosing the first in the panel's list and pressing Space
   steps the first snake only.
3. Exports through the file dialogs: the selected snake as JSON and OBJ, all snakes as PLY,
   each file parsed and compared with the tool's own state; exporting over the mesh itself
   (confirming the dialog's "replace?") is refused and the mesh is unchanged byte for byte.
4. Add as layer: a new layer appears; saved with MeshLab's own Export Mesh As (OBJ), it holds
   the curve's vertices.
5. Deleting the mesh while the tool is active (R pressed just before): MeshLab ends the tool (the
   Run ends, the session is saved), the layer is gone, MeshLab keeps running; started again on
   the edge layer left, the panel comes back and says that layer has no faces; keys do no harm.
"""
import json
import math
import os
import re
import signal
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402  (the MeshLab driver, screenshots, cube geometry, the tool's JSON and Log)
from gui import changed, read_bytes, samples, save_dialog, snakes_of, wait_for  # noqa: E402

check, log, xdo = g.check, g.log, g.xdo

# Fixed positions in the 1600x1000 main window, the panel docked on the left, MeshLab's layer
# dialog on the right (see 20_panel.png)
PANEL_EXPORT_SELECTED = (82, 628)
PANEL_EXPORT_ALL = (254, 628)
PANEL_ADD_LAYER = (92, 660)
PANEL_NEW = (92, 555)
PANEL_LIST = (173, 525)
MENU_DELETE_MESH = (1360, 250)  # in the context menu of the first layer (26_layer_menu.png)
LAYER_ROW = [(1283, 114), (1313, 145)]  # first and second layer in the layer dialog
STATUS_BOTTOM = 110  # the status line's bottom edge, from the top of the panel


def positions(j, k=0):
    return [tuple(x["position"]) for x in samples(j)[k]["samples"]]


def pins(j, k=0):
    return [i for i, x in enumerate(samples(j)[k]["samples"]) if x["fixed"]]


def close_to(a, b, tol=1e-5):
    return len(a) == len(b) and all(math.dist(p, q) <= tol for p, q in zip(a, b))


def test(WORK):
    mesh = g.copy_data("icocube.ply")
    mesh_bytes = read_bytes(mesh)
    V, F = g.mesh_ply(mesh)
    h = g.mean_edge(V, F)
    auto = os.path.join(WORK, "auto.json")

    with g.MeshLab(mesh, "run", kill=signal.SIGKILL) as ml:
        face = g.start_on_front_face(ml, "20_panel.png")
        if not face:
            return
        left, right, top, bottom = face
        hpx = (right - left) / 2.0 * h
        xm = (left + right) // 2
        s0 = g.build_from_clicks(auto, left, right, top + 2.2 * hpx, min_samples=5)
        if not check(bool(s0), "Enter builds the snake"):
            return
        n0 = len(samples(s0)[0]["samples"])

        # ------------------------------------------------------------ 1. keys: insert, pin, delete
        time.sleep(1.0)
        img = g.Image(g.screenshot("21_built.png"))
        ym = g.snake_rows(img, xm)
        check(bool(ym), "the snake is drawn")
        xdo("mousemove", xm, ym[len(ym) // 2] if ym else int(top + 2.2 * hpx), "click", 1)  # selects a sample
        time.sleep(0.5)
        xdo("key", "i")
        s1 = changed(auto, s0)
        ok = bool(s1) and len(samples(s1)[0]["samples"]) == n0 + 1
        check(ok, "I inserts a sample (%d -> %s)" % (n0, len(samples(s1)[0]["samples"]) if s1 else "?"))
        if ok:
            p0, p1 = positions(s0), positions(s1)
            new = [i for i in range(len(p1)) if p1[:i] + p1[i + 1:] == p0]
            check(len(new) == 1, "the other samples stay exactly where they were (new sample at %s)" % new)
            ins = new[0] if new else -1
            if 0 < ins < len(p1) - 1:
                a, b, c = p1[ins - 1], p1[ins], p1[ins + 1]
                check(math.dist(a, b) < math.dist(a, c) and math.dist(b, c) < math.dist(a, c),
                      "the new sample lies between its neighbours")
        xdo("key", "p")
        s2 = changed(auto, s1)
        check(bool(s2) and pins(s2) == [ins], "P pins the inserted (current) sample (%s)" % (pins(s2) if s2 else "?"))
        xdo("key", "p")
        s3 = changed(auto, s2)
        check(bool(s3) and pins(s3) == [] and positions(s3) == positions(s1), "P again unpins it")
        xdo("key", "Delete")
        s4 = changed(auto, s3)
        check(bool(s4) and positions(s4) == positions(s0), "Delete removes it: the snake as built")
        history = [("ctrl+z", s3, "unpinned"), ("ctrl+z", s2, "pinned"), ("ctrl+z", s1, "inserted"),
                   ("ctrl+y", s2, "pinned"), ("ctrl+y", s3, "unpinned")]
        cur = s4
        for k, (key, want, name) in enumerate(history):
            xdo("key", key)
            cur = changed(auto, cur)
            check(bool(cur) and samples(cur)[0]["samples"] == samples(want)[0]["samples"],
                  "%s (%d of 5) returns to the %s state" % (key, k + 1, name))
        xdo("key", "ctrl+y")  # back to the snake as built (the sample deleted)
        cur = changed(auto, cur)
        check(bool(cur) and positions(cur) == positions(s0), "Ctrl+Y redoes the delete")

        # ------------------------------------------------------------ 2. several snakes
        xdo("key", "r")
        conv = wait_for(lambda: (lambda j: j if j and samples(j)[0]["stats"]["converged"] else None)(snakes_of(auto)), 60)
        check(bool(conv), "the first snake converges")
        time.sleep(0.5)
        xdo("mousemove", *PANEL_NEW, "click", 1)
        time.sleep(0.5)
        for f in (0.3, 0.5, 0.7):
            xdo("mousemove", int(left + f * (right - left)), int((top + bottom) / 2), "click", 1)
            time.sleep(0.4)
        xdo("key", "Return")
        two = wait_for(lambda: (lambda j: j if j and len(samples(j)) == 2 else None)(snakes_of(auto)), 20)
        if not check(bool(two), "New, seeds and Enter build a second snake"):
            return
        check(samples(two)[0]["stats"]["converged"] and samples(two)[0]["samples"] == samples(conv)[0]["samples"],
              "the first snake keeps its state and its \"converged\"")
        xdo("mousemove", *PANEL_LIST, "click", 1)  # the list: its popup ...
        time.sleep(0.8)
        g.screenshot("22_list.png")
        xdo("key", "Up", "Return")  # ... choose the first snake
        time.sleep(0.5)
        ops = [x["stats"]["operations"] for x in samples(two)]
        xdo("key", "space")
        stepped = changed(auto, two)
        ops2 = [x["stats"]["operations"] for x in samples(stepped)] if stepped else None
        check(ops2 == [ops[0] + 1, ops[1]], "after choosing snake 1 in the list, Space steps snake 1 only (%s -> %s)" % (
            ops, ops2))
        state = snakes_of(auto)

        # ------------------------------------------------------------ 3. exports through the dialogs
        def export(button, title, name, confirm=False):
            xdo("mousemove", *button, "click", 1)
            path = os.path.join(WORK, name)
            if not check(save_dialog(title, path, confirm), "the dialog \"%s\" opens" % title):
                xdo("key", "Escape")
                return None
            time.sleep(1.5)
            return path

        p = export(PANEL_EXPORT_SELECTED, "Export the selected snake", "selected.json")
        if p and check(os.path.exists(p), "Export selected... writes JSON"):
            j = json.load(open(p))
            check("snakes" not in j and j["samples"] == samples(state)[0]["samples"],
                  "the JSON holds the selected snake (snake 1) exactly")
        p = export(PANEL_EXPORT_SELECTED, "Export the selected snake", "selected.obj")
        if p and check(os.path.exists(p), "Export selected... writes OBJ"):
            lines = open(p).read().split("\n")
            v = [tuple(map(float, l.split()[1:])) for l in lines if l.startswith("v ")]
            ls = [l for l in lines if l.startswith("l ")]
            check(close_to(v, [tuple(x) for x in samples(state)[0]["polyline"]], 1e-6) and len(ls) == 1 and
                  len(ls[0].split()) == len(v) + 1, "the OBJ holds snake 1's curve as one polyline (%d vertices)" % len(v))
        p = export(PANEL_EXPORT_ALL, "Export all snakes", "all.ply")
        if p and check(os.path.exists(p), "Export all... writes PLY"):
            text = open(p).read()
            nv = int(re.search(r"element vertex (\d+)", text).group(1))
            ne = int(re.search(r"element edge (\d+)", text).group(1))
            want = sum(len(x["polyline"]) for x in samples(state))
            check(nv == want and ne == want - 2, "the PLY holds both curves (%d vertices, %d edges)" % (nv, ne))
        g.screenshot("23_exports.png")

        # ------------------------------------------------------------ 4. Add as layer, saved by MeshLab
        xdo("mousemove", *PANEL_ADD_LAYER, "click", 1)
        check(wait_for(lambda: "Geometric snake: added layer icocube snake 1" in ml.log_text(), 5),
              "Add as layer adds the selected curve as a new layer")
        xdo("mousemove", *LAYER_ROW[1], "click", 1)  # the new layer becomes current
        time.sleep(1.5)
        g.screenshot("24_layer.png")
        xdo("key", "ctrl+shift+e")  # File > Export Mesh As...
        layer_obj = os.path.join(WORK, "layer.obj")
        if check(save_dialog("snake 1. Layer", layer_obj), "MeshLab's Export Mesh As dialog opens"):
            time.sleep(1.5)
            g.screenshot("25_save_options.png")
            xdo("key", "Return")  # the saving options: OK
            time.sleep(1.5)
        if check(wait_for(lambda: os.path.exists(layer_obj), 5), "MeshLab saves the layer"):
            v = [tuple(map(float, l.split()[1:4])) for l in open(layer_obj) if l.startswith("v ")]
            want = [tuple(x) for x in samples(state)[0]["polyline"]]
            check(close_to(v, want, 1e-5), "the saved layer has the curve's vertices (%d of %d)" % (len(v), len(want)))

        xdo("mousemove", *LAYER_ROW[0], "click", 1)  # back on the cube: the tool restarts there
        time.sleep(1.5)

        # ------------------------------------------------------------ 3b. never over the mesh
        # and the long message that says so (it names the mesh's whole path) stays in the status
        # line: the panel keeps its width and its buttons stay where they were
        xdo("mousemove", 640, 990)  # no hover highlight on the panel in the screenshots
        time.sleep(0.5)
        panel_before = g.Image(g.screenshot("23b_panel_before.png"))
        xdo("mousemove", *PANEL_EXPORT_ALL, "click", 1)
        save_dialog("Export all snakes", mesh, confirm_replace=True)
        time.sleep(1.5)
        text = ml.log_text()
        check(read_bytes(mesh) == mesh_bytes, "exporting over the mesh through the dialog leaves it unchanged")
        m = re.search(r"LOG: 1 (Refusing to write .*icocube\.ply.*)", text)
        check(bool(m), "... and the Log says why (%s)" % (m.group(1) if m else "no warning"))
        xdo("mousemove", 640, 990)
        time.sleep(0.5)
        panel_after = g.Image(g.screenshot("23c_panel_long_message.png"))
        pg = g.panel_geometry(text)
        if check(bool(pg) and pg[0], "the panel is docked (its Log line)"):
            _, px, py, pw, ph = pg
            rows = [y for y in range(max(0, py - 4), min(panel_after.h, py + ph)) if any(
                panel_before.px(x, y) != panel_after.px(x, y) for x in range(max(0, px - 40), min(panel_after.w, px + pw)))]
            log("panel at %d,%d %dx%d; rows changed by the long message: %s" % (
                px, py, pw, ph, "%d..%d" % (rows[0] - py, rows[-1] - py) if rows else "none"))
            check(bool(rows), "the long message shows in the panel")
            check(bool(rows) and rows[-1] - py < STATUS_BOTTOM,
                  "only the status line changed: the dock kept its width and the buttons below did not move")
            reds = g.red_pixels(os.path.join(WORK, "23c_panel_long_message.png"), px, py, pw, STATUS_BOTTOM)
            check(reds > 40, "the status line shows the message in red (%d red pixels)" % reds)
        xdo("mousemove", *PANEL_EXPORT_ALL, "click", 1)  # the button is where it was
        check(bool(wait_for(lambda: xdo("search", "--name", "Export all snakes").split(), 5)),
              "after the long message, Export all... still opens its dialog")
        xdo("key", "Escape")
        time.sleep(0.5)

        # ------------------------------------------------------------ 5. deleting the mesh
        count = lambda what: ml.log_text().count(what)
        panels, nofaces = count("panel docked"), count("has no faces")
        xdo("key", "r")  # a Run (the tool owns R in the layer dialog too) ...
        xdo("mousemove", *LAYER_ROW[0], "click", 3)  # ... and the cube's context menu: Filters > Mesh Layer
        time.sleep(1.0)
        g.screenshot("26_layer_menu.png")
        xdo("mousemove", *MENU_DELETE_MESH, "click", 1)  # Delete Current Mesh
        check(wait_for(lambda: "Applied filter Delete Current Mesh" in ml.log_text(), 10), "the cube layer is deleted")
        time.sleep(1.5)
        g.screenshot("27_deleted.png")
        check(ml.p.poll() is None, "MeshLab keeps running")
        # (the line saying MeshLab ended the tool comes between: left out)
        text = re.sub(r"[^\n]*Geometric snake: MeshLab ended the tool[^\n]*\n", "", ml.log_text())
        last_run = max((m.end() for m in re.finditer(r"Geometric snake: Run (converged|stopped) after", text)), default=-1)
        check(0 <= text.find("Applied filter Delete Current Mesh") - last_run < 400,
              "the Run ended (its Log line) just before the mesh was deleted")
        sc = snakes_of(mesh + ".snakes.json")
        check(bool(sc) and len(sc["snakes"]) == 2, "the tool saved both snakes to the sidecar as it ended")
        # started again: the panel comes back and says the remaining (edge) layer has no faces
        xdo("mousemove", 70, 10, "click", 1)
        time.sleep(1)
        xdo("mousemove", 141, 84, "click", 1)
        check(wait_for(lambda: count("panel docked") == panels + 1, 10), "the tool starts again, with its panel")
        check(wait_for(lambda: count("has no faces") == nofaces + 1, 5), "the panel says the layer left has no faces")
        xdo("mousemove", 400, 500, "click", 1)
        xdo("key", "r", "space", "Delete", "ctrl+z")
        time.sleep(1.0)
        g.screenshot("28_restarted.png")
        check(ml.p.poll() is None, "keys with no mesh to work on do no harm")


if __name__ == "__main__":
    g.main("edit_gui_edit", test)
