#!/usr/bin/env python3
"""Inside a Debian root, under Xvfb: that release's MeshLab GUI starts with the installed
plugins, shows no plugin-loading error, and the Geometric Snake edit tool starts on a mesh
(GS_SNAKE_AUTOSTART=1 triggers its action as soon as MeshLab has the mesh; MeshLab logs
"Started Mode Geometric Snake" only when the tool's startEdit succeeded). With --clicks, the
user's first steps too, as tests/host/test_edit_gui.py does them in MeshLab 2020.09: the panel
docks in the main window, four clicks on the cube's front face and Enter build a snake, R runs it
onto the cube's edge (screenshots with xwd, tests/debian13/xwd_image.py), and the panel's Cut
buttons select, split and cut a plate along a square snake.

    xvfb-run -n N -s "-screen 0 1600x1024x24" python3 gui_in_root.py MESH WORK_DIR [VERSION] [--clicks]
    (VERSION: MeshLab's, e.g. 2022.02 (default) or 2025.07; its main window's title starts with it)
"""
import json
import os
import re
import shutil
import subprocess
import sys
import time

args = [a for a in sys.argv[1:] if not a.startswith("--")]
mesh, work = args[0], args[1]
version = args[2] if len(args) > 2 else "2022.02"
clicks = "--clicks" in sys.argv
shutil.rmtree(work, ignore_errors=True)  # no sidecar, auto-export or settings of an earlier run
os.makedirs(work)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "host"))
from checks import check, failures  # noqa: E402
def windows(name):
    out = subprocess.run(["xdotool", "search", "--name", name], capture_output=True, text=True).stdout
    return out.split()


def overlap(a, b):
    ax, ay, aw, ah = a
    bx, by, bw, bh = b
    return ax < bx + bw and bx < ax + aw and ay < by + bh and by < ay + ah


def boxes(text):
    """The panel, 3D view and layer dialog boxes the tool logs once the main window has laid the
    panel out (edit_snake_view.cpp): (docked?, panel, view, layer dialog, its state) or None."""
    p = re.findall(r"panel (docked|floating) in MeshLab's main window at (-?\d+),(-?\d+) size (\d+)x(\d+)", text)
    v = re.findall(r"3D view at (-?\d+),(-?\d+) size (\d+)x(\d+)", text)
    l = re.findall(r"layer dialog \(with the Log\) at (-?\d+),(-?\d+) size (\d+)x(\d+), (\w+)", text)
    if not (p and v and l):
        return None
    return (p[-1][0] == "docked", tuple(map(int, p[-1][1:])), tuple(map(int, v[-1])), tuple(map(int, l[-1][:4])), l[-1][4])


def check_layout(text):
    """Issue 37 in this MeshLab: the panel docks in the main window beside the 3D view (left of it
    by default), and MeshLab's layer dialog with its Log stays visible, not under a tab."""
    b = boxes(text)
    if not check(b is not None, "the tool logs where its panel, the 3D view and the layer dialog are"):
        return None
    docked, panel, view, layers, state = b
    print("panel %s, view %s, layer dialog %s (%s)" % (panel, view, layers, state), flush=True)
    check(docked, "the panel docks in MeshLab %s's main window" % version)
    check(panel[0] + panel[2] <= view[0] + 2, "the panel is left of the 3D view (its default place)")
    check(not overlap(panel, view), "the panel does not cover the 3D view")
    check(state == "visible" and not overlap(panel, layers),
          "MeshLab's layer dialog, with the Log, stays visible beside the panel (not a tab under it)")
    return view


def view_box(img):
    """The 3D view on a screenshot: the extent of its background gradient (black to blue, blue
    twice red and green) along a row at 40 % of the height and a column at its left edge (the
    tool's logged boxes date from before the window took its final size when the tool starts
    with MeshLab)."""
    bg = lambda p: p[2] >= 4 and p[2] >= 1.6 * max(p[0], 1) and abs(p[0] - p[1]) < 6
    y = img.h * 2 // 5
    xs = [x for x in range(img.w) if bg(img.px(x, y))]
    if not xs:
        return None
    ys = [yy for yy in range(img.h) if bg(img.px(xs[0] + 2, yy))]
    return (xs[0], ys[0], xs[-1] + 1, ys[-1] + 1) if ys else None


def mesh_pixels(img, box):
    import gui  # tests/host, on the path once with_clicks runs
    x0, y0, x1, y1 = box
    return sum(1 for y in range(y0, y1, 3) for x in range(x0, x1, 3) if gui.is_mesh(img.px(x, y)))


def started_only():
    env = dict(os.environ, LIBGL_ALWAYS_SOFTWARE="1", GS_SNAKE_AUTOSTART="1",
               XDG_CONFIG_HOME=os.path.join(work, "config"), XDG_RUNTIME_DIR=os.path.join(work, "runtime"))
    os.makedirs(env["XDG_RUNTIME_DIR"], mode=0o700, exist_ok=True)
    logpath = os.path.join(work, "meshlab.log")
    with open(logpath, "w") as logf:
        p = subprocess.Popen(["meshlab", mesh], stdout=logf, stderr=subprocess.STDOUT, env=env, start_new_session=True)
        started = False
        main_window = []
        for _ in range(180):
            time.sleep(0.5)
            main_window = main_window or windows("MeshLab " + version[:4])
            text = open(logpath, errors="replace").read()
            if "Started Mode Geometric Snake" in text or p.poll() is not None:
                started = "Started Mode Geometric Snake" in text
                break
        time.sleep(1)
        check(p.poll() is None, "MeshLab %s is running" % version)
        check(bool(main_window), "MeshLab's main window appeared (title 'MeshLab %s...')" % version)
        check(not windows("Error while loading plugins"), "no 'Error while loading plugins' dialog (every plugin loaded)")
        check(started, "the Geometric Snake edit tool started on %s ('Started Mode Geometric Snake')" % os.path.basename(mesh))
        # the panel docks in MeshLab's main window and says where in the Log
        for _ in range(10):
            text = open(logpath, errors="replace").read()
            if boxes(text):
                break
            time.sleep(0.5)
        check_layout(text)
        p.terminate()
        try:
            p.wait(10)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()
    if failures:
        print("--- MeshLab output (%s)" % logpath)
        print(open(logpath, errors="replace").read()[-4000:])


def with_clicks():
    """tests/host/gui.py's MeshLab (window at 0,0, 1600x1000, fresh settings, the tool's JSON
    auto-exported after every change), the tool started by GS_SNAKE_AUTOSTART, not by the menu."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import xwd_image  # puts tests/host (gui.py) on the path
    import gui
    gui.WORK = work
    os.environ["GS_SNAKE_AUTOSTART"] = "1"
    os.environ["GS_SNAKE_PANEL_STATE"] = state_path = os.path.join(work, "panel.json")  # edit_snake_status.cpp

    def panel_state():
        try:
            return json.load(open(state_path))
        except (OSError, ValueError):
            return None
    local = os.path.join(work, os.path.basename(mesh))
    with open(mesh, "rb") as s, open(local, "wb") as d:  # the tool autosaves beside the mesh
        d.write(s.read())
    V, F = gui.mesh_ply(local)
    h = gui.mean_edge(V, F)
    auto = os.path.join(work, "auto.json")
    ml = gui.MeshLab(local, "clicks")
    try:
        text = gui.wait_for(lambda: (lambda t: t if "Started Mode Geometric Snake" in t else None)(ml.log_text()), 60)
        check(bool(text), "the Geometric Snake edit tool started on %s" % os.path.basename(mesh))
        check(not windows("Error while loading plugins"), "no 'Error while loading plugins' dialog (every plugin loaded)")
        check(ml.win is not None and bool(windows("MeshLab " + version[:4])),
              "MeshLab's main window is MeshLab %s's" % version)
        # the tool logs where its panel is once the main window has laid it out
        check_layout(gui.wait_for(lambda: (lambda t: t if boxes(t) else None)(ml.log_text()), 5) or ml.log_text())
        img = xwd_image.screenshot("01_started.xwd")
        left, right, top, bottom = gui.front_face_extent(img)
        hpx = (right - left) / 2.0 * h  # the front face spans 2 units
        print("front face px: x %d..%d y %d..%d, h = %.4f = %.1f px" % (left, right, top, bottom, h, hpx), flush=True)
        if not check(right - left > 100 and bottom - top > 100, "the cube's front face is on screen"):
            return
        j = gui.build_from_clicks(auto, left, right, int(top + 2.2 * hpx), min_samples=5)
        if not check(j is not None and len(gui.samples(j)) == 1, "four clicks and Enter build a snake"):
            return
        s = gui.samples(j)[0]
        d0 = [gui.dist_cube_edges(x["position"]) for x in s["samples"][1:-1]]
        check(sum(d0) / len(d0) > 1.0 * h, "the snake starts away from the edge (mean %.2f h)" % (sum(d0) / len(d0) / h))
        gui.xdo("key", "r")
        j = gui.wait_for(lambda: (lambda j: j if j and gui.samples(j)[0]["stats"]["converged"] else None)(
            gui.snakes_of(auto)), 90)
        if not check(j is not None, "R runs the snake to convergence"):
            return
        s = gui.samples(j)[0]
        pos = [x["position"] for x in s["samples"][1:-1]]
        onmesh = gui.edge_on_mesh(V, F, h, *gui.nearest_cube_edge(pos[len(pos) // 2]))
        dm = [gui.dist_polyline(p, onmesh) for p in pos]
        check(sum(dm) / len(dm) < 0.25 * h, "the snake converged onto the cube's edge (%d operations; mean %.3f h, max %.3f h)"
              % (s["stats"]["operations"], sum(dm) / len(dm) / h, max(dm) / h))
        runs = gui.run_lines(ml.log_text())
        check(bool(runs) and runs[-1][0] == "converged", "the Log says the Run converged: %s" % (runs[-1:],))
        # The wheel zooms the view with the tool active (issue 37), and the tool stays active: R
        # still runs the snake.
        before_img = xwd_image.screenshot("02_converged.xwd")
        box = view_box(before_img)
        if check(box is not None, "the 3D view's background is on screen (%s)" % (box,)):
            before = mesh_pixels(before_img, box)
            gui.xdo("mousemove", (left + right) // 2, (top + bottom) // 2, "click", 4, "click", 4)
            time.sleep(1.0)
            after = mesh_pixels(xwd_image.screenshot("03_after_wheel.xwd"), box)
            check(after < 0.8 * before, "the wheel zooms the view with the tool active (mesh pixels %d -> %d)" % (before, after))
            gui.xdo("key", "r")
            more = gui.wait_for(lambda: len(gui.run_lines(ml.log_text())) > len(runs), 10)
            check(bool(more), "the tool is still active after the wheel: R runs the snake again (%s)"
                  % (gui.run_lines(ml.log_text())[-1:],))
    finally:
        ml.kill()
        if failures:
            print("--- MeshLab output (%s)" % ml.logpath)
            print(ml.log_text()[-4000:])


def with_cut():
    """Issue 34 in this MeshLab: the panel's Cut buttons, found through the panel-state hook (the
    release's fonts and style move them), on a flat 10 x 10 plate whose session holds a closed
    square snake round [2.5, 7.5]^2, as tests/host/test_edit_gui_cut.py does in 2020.09: Select
    inside embeds the square and selects exactly its inside (area 25 of 100), Split into layers
    adds the two layers, Cut open makes the square's edges boundary edges."""
    import xwd_image  # puts tests/host (gui.py, mlhost.py) on the path
    import gui
    import mlhost
    panel = gui.panel_state_reader(os.path.join(work, "panel_cut.json"))
    mesh, _, curve = mlhost.plate_and_square(work)
    with open(mesh + ".snakes.json", "w") as f:  # the tool restores it when it starts
        json.dump({"format": "geometric-snake-session", "version": 1, "mesh": {"vertices": 121, "faces": 200},
                   "snakes": [curve], "selected": 0}, f)
    ml = gui.MeshLab(mesh, "cut", autoexport=False)
    log = lambda pattern, timeout=10: gui.wait_for(lambda: re.search(pattern, ml.log_text()), timeout)
    try:
        if not check(bool(log("Started Mode Geometric Snake", 60)), "the tool started on the plate"):
            return
        # room for the Cut section (last, closed by default): the sections above it closed
        for title in ("Seeds", "Editing (selected sample)", "Output"):
            gui.set_section(panel, title, False)
        if not check(gui.set_section(panel, "Cut", True), "a click opens the panel's Cut section"):
            return
        xwd_image.screenshot("cut_01_section.xwd")
        check(gui.click_widget(panel, "Select inside"), "the Select inside button is shown")
        m = log(r"Selected the inside of snake 1: (\d+) faces \(area ([0-9.]+) of ([0-9.]+)\)\. The snake was embedded "
                r"into the mesh: (\d+) vertices and (\d+) faces added")
        check(bool(m) and float(m.group(2)) == 25 and float(m.group(3)) == 100,
              "Select inside embeds the square and selects exactly its inside: %s"
              % ("%s faces, area %s of %s (%s vertices, %s faces added)" % m.groups() if m else "no Log line"))
        xwd_image.screenshot("cut_02_inside.xwd")
        check(gui.click_widget(panel, "Split into layers"), "the Split into layers button is shown")
        m = log(r"Split along snake 1 into layers \"plate inside\" \((\d+) faces\) and \"plate outside\" \((\d+) faces\)")
        check(bool(m), "Split into layers adds the inside and outside layers: %s" % (m.group(0) if m else "no Log line"))
        check(gui.click_widget(panel, "Cut open"), "the Cut open button is shown")
        m = log(r"Cut open along snake 1: its (\d+) vertices on the mesh are on the boundary now \((\d+) vertices")
        check(bool(m) and int(m.group(2)) >= int(m.group(1)),
              "Cut open gives the curve's vertices a copy on the other side (%s)" % (m.groups() if m else "no Log line",))
        xwd_image.screenshot("cut_03_done.xwd")
    finally:
        ml.kill()
        if failures:
            print("--- MeshLab output (%s)" % ml.logpath)
            print(ml.log_text()[-4000:])


if clicks:
    with_clicks()
    with_cut()
else:
    started_only()
sys.exit(1 if failures else 0)
