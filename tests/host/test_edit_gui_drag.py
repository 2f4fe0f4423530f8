#!/usr/bin/env python3
"""GUI test of a drag on a grazing view (issue 11), in the real MeshLab.

Run under an X server (CTest: xvfb-run ... test_edit_gui_drag.py <work folder>), on
data/icocube.ply (cube [-1,1]^3): a snake is built below the top edge of the front face and Run
onto that edge. The view is then tilted (Esc suspends the tool, a left drag turns the trackball)
until the top face shows edge-on: a few tens of pixels high for its 2 units of depth, so that a
pixel on it spans several edge lengths. A sample on the edge is dragged 40 px up onto the top face
in 5 mouse moves.
- Bounded: the tool moves the sample at most 2 x (pixels moved + 2) pixel sizes (the size of a
  pixel at the sample's depth, facing the view) per mouse event. The surface point under the
  cursor is 40 px / sin(tilt) pixel sizes away, about 4x the bound here: without the bound the
  sample lands there and the check fails (measured with boundedDragTarget disabled: the pin moved
  10.3 edge lengths against a bound of 3.1; with it, 1.7).
- No tangle: Run again; the snake (exported JSON) still runs along the edge in order (its samples'
  coordinate along the edge increases monotonically, so it does not fold or cross itself), every
  sample stays within the pin's offset + 1 edge length of the edge, and the curve is at most the
  length before the drag + 2x the pin's offset + 2 edge lengths.
"""
import math
import os
import signal
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402  (the MeshLab driver, screenshots, cube geometry, the tool's JSON)
from gui import check, log, samples, snakes_of, wait_for, xdo  # noqa: E402

DRAG_PX, DRAG_EVENTS = 40, 5


def is_surface(p):
    """Any shade of the mesh's grey, also the dark grey of a face seen edge-on (the background is blue)."""
    return p[0] > 25 and abs(p[0] - p[1]) < 14 and abs(p[1] - p[2]) < 14


def top_face_height(img, x, y_edge):
    """Pixels of the top face above the front face's top edge at column x (the face seen edge-on):
    surface pixels up from the snake (past its dark outline) to the first background pixels."""
    y, gap = y_edge - 6, 0
    while y > 70 and gap < 3:
        gap = 0 if is_surface(img.px(x, y)) else gap + 1
        y -= 1
    return y_edge - y - gap


def edge_y(img, x):
    """The snake's row at column x (it lies on the front face's top edge)."""
    ys = g.snake_rows(img, x)
    return ys[len(ys) // 2] if ys else None


def polyline_length(pts, closed=False):
    n = len(pts)
    return sum(math.dist(pts[i], pts[(i + 1) % n]) for i in range(n if closed else n - 1))


def test(WORK):
    mesh = g.copy_data("icocube.ply")
    V, F = g.mesh_ply(mesh)
    h = g.mean_edge(V, F)
    auto = os.path.join(WORK, "auto.json")

    with g.MeshLab(mesh, "run", kill=signal.SIGKILL) as ml:
        face = g.start_on_front_face(ml, "01_started.png")
        if not face:
            return
        left, right, top, bottom = face
        hpx = (right - left) / 2.0 * h
        xm = (left + right) // 2
        if not check(bool(g.build_from_clicks(auto, left, right, top + 2.2 * hpx)), "Enter builds the snake"):
            return
        xdo("key", "r")
        conv = wait_for(lambda: (lambda j: j if j and samples(j)[0]["stats"]["converged"] else None)(snakes_of(auto)), 60)
        if not check(bool(conv), "Run: the snake converges onto the top edge of the front face"):
            return
        pos0 = [tuple(x["position"]) for x in samples(conv)[0]["samples"]]
        edge = g.nearest_cube_edge(pos0[len(pos0) // 2])
        axis = next(k for k in range(3) if edge[0][k] != edge[1][k])  # the edge runs along this axis
        log("the snake lies on the cube edge %s - %s" % edge)

        # ---- tilt the view until the top face is seen edge-on (a few tens of pixels high)
        xdo("mousemove", 400, 950, "click", 1)  # focus the 3D view, away from the snake
        time.sleep(0.3)
        xdo("key", "Escape")  # suspends the tool: the mouse turns the trackball
        time.sleep(0.5)
        tilt = None
        for k in range(60):
            img = g.Image(g.screenshot("02_tilt.png"))
            ye = edge_y(img, xm)
            if ye is None:
                break
            t = top_face_height(img, xm, ye)
            log("tilt step %d: the snake at row %d, the top face %d px high" % (k, ye, t))
            if t >= 45:
                tilt = (ye, t)
                break
            # down through the middle: the top of the cube turns towards the viewer (seen in
            # perspective from below its plane, it shows once the turn passes ~20 degrees; then
            # it grows fast: smaller turns)
            x0, _, x1, _ = g.gl_box(img)
            g.drag((x0 + x1) // 2 - 22, 400, 0, 8 if t < 12 else 3, 2)
            time.sleep(0.5)
        xdo("key", "Escape")  # resumes the tool
        time.sleep(0.5)
        img = g.Image(g.screenshot("03_grazing.png"))
        if not check(tilt is not None and tilt[1] <= 120, "a grazing view of the top face (%s px high for 2 units)" % (
                tilt[1] if tilt else "?")):
            return
        left, right, _, _ = g.front_face_extent(img)
        pixel = 2.0 / (right - left)  # the size of a pixel at the edge's depth (the front face spans 2 units)
        ye = edge_y(img, xm)
        grazing = 2.0 / (tilt[1] * pixel)  # pixel sizes per pixel on the top face: 1 / sin(tilt)
        log("pixel size %.4f = %.3f h; on the top face a pixel spans %.1f pixel sizes" % (pixel, pixel / h, grazing))

        # ---- the drag: 40 px up onto the top face, in 5 mouse moves
        x, y = g.sample_near(img, xm, ye)
        g.drag(x, y, 0, -DRAG_PX, DRAG_EVENTS, pause=0.15)
        dragged = wait_for(lambda: (lambda j: j if j and any(x["fixed"] for x in samples(j)[0]["samples"]) else None)(
            snakes_of(auto)), 10)
        if not check(bool(dragged), "the drag moves and pins a sample"):
            return
        g.screenshot("04_dragged.png")
        pin = next(i for i, x in enumerate(samples(dragged)[0]["samples"]) if x["fixed"])
        pinpos = tuple(samples(dragged)[0]["samples"][pin]["position"])
        moved = math.dist(pinpos, pos0[pin])
        bound = 2 * (DRAG_PX + 2 * DRAG_EVENTS) * pixel
        under = DRAG_PX * grazing * pixel  # the surface point under the cursor: where an unbounded drag lands
        log("the pin moved %.3f (%.1f h); bound %.3f (%.1f h); the point under the cursor is ~%.3f (%.1f h) away" % (
            moved, moved / h, bound, bound / h, under, under / h))
        check(under > 1.5 * bound, "the view is grazing enough that an unbounded drag would exceed the bound")
        check(moved > 5 * pixel, "the sample follows the cursor (%.1f pixel sizes)" % (moved / pixel))
        check(moved <= 1.1 * bound, "on the grazing view the sample moved at most 2 x (pixels + 2) pixel sizes per "
              "mouse event: %.1f h <= %.1f h" % (moved / h, 1.1 * bound / h))
        off = g.dist_seg(pinpos, *edge)

        # ---- the next Run does not tangle the snake
        xdo("key", "r")
        rerun = wait_for(lambda: (lambda j: j if j and j != dragged and (samples(j)[0]["stats"]["converged"] or
                                                                       "Run stopped" in ml.log_text()) else None)(
            snakes_of(auto)), 60)
        if not check(bool(rerun), "the Run after the drag ends"):
            return
        time.sleep(1.0)
        rerun = snakes_of(auto)
        g.screenshot("05_rerun.png")
        s = samples(rerun)[0]
        pos = [tuple(x["position"]) for x in s["samples"]]
        # the pinned sample, found by its flag: a snake that lengthens inserts samples (its
        # indices move), the pin must stay where the drag left it
        pinned = [tuple(x["position"]) for x in s["samples"] if x["fixed"]]
        check(pinned == [pinpos], "the pin held")
        along = [p[axis] for p in pos]
        sign = 1 if along[-1] > along[0] else -1
        steps = [sign * (b - a) for a, b in zip(along, along[1:])]
        check(min(steps) > 0, "the samples run along the edge in order: no fold, no crossing (smallest step %.3f h)" % (
            min(steps) / h))
        far = max(g.dist_seg(p, *edge) for p in pos)
        check(far <= off + h, "every sample within the pin's offset + 1 edge length of the edge (%.2f h <= %.2f h)" % (
            far / h, (off + h) / h))
        L0, L = polyline_length(pos0), polyline_length(pos)
        check(L <= L0 + 2 * off + 2 * h, "the curve's length is sane: %.2f h (before the drag %.2f h, pin offset %.2f h)" % (
            L / h, L0 / h, off / h))


if __name__ == "__main__":
    g.main("edit_gui_drag", test)
