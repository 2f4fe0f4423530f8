#!/usr/bin/env python3
"""GUI test: on a 1.2M-face mesh a seed click shows within 100 ms and Build ends within 300 ms (issue 37).

Run under an X server (CTest: xvfb-run ... test_edit_gui_large.py <work folder>). The issue's case:
bunny00 (../shared/data/meshes) subdivided twice (midpoint, 1.2M faces, written here as binary PLY
and kept beside the work folder for the next run); MeshLab opens it, the tool starts, four clicks
across the bunny place seeds, Enter builds the open snake. The tool logs, for each input, the time
from the input to the redraw that shows it ("seed shown 40 ms after the input (tool 2 ms, redraw
38 ms)", edit_snake_response.h); the test prints them all and checks the median click and the
Build against the targets. GS_LARGE_GUI_STRICT=0 prints without checking the times (a loaded
machine), the other checks stay.
"""
import os
import re
import shutil
import statistics
import struct
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gui as g  # noqa: E402  (the MeshLab driver, the tool's JSON and Log)
from gui import Image, check, log, samples, snakes_of, wait_for, xdo  # noqa: E402

MESHES = os.path.join(g.DATA, "..", "..", "shared", "data", "meshes")
CLICK_MS, BUILD_MS = 100, 300  # the targets


def read_off(path):
    tok = open(path).read().split()
    nv, nf = int(tok[1]), int(tok[2])
    V = [tuple(map(float, tok[4 + 3 * i:7 + 3 * i])) for i in range(nv)]
    o = 4 + 3 * nv
    F = [tuple(map(int, tok[o + 4 * i + 1:o + 4 * i + 4])) for i in range(nf)]
    return V, F


def midpoint(V, F):
    """Each triangle into four, midpoints shared between the two faces of an edge."""
    V, mid, out = list(V), {}, []

    def m(a, b):
        k = (a, b) if a < b else (b, a)
        i = mid.get(k)
        if i is None:
            pa, pb = V[a], V[b]
            i = mid[k] = len(V)
            V.append(((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2))
        return i
    for a, b, c in F:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        out += [(ab, bc, ca), (a, ab, ca), (b, bc, ab), (c, ca, bc)]
    return V, out


def subdivided_bunny(src, path):
    """bunny00 subdivided twice as binary PLY at `path` (made once, then reused)."""
    if os.path.exists(path) and os.path.getmtime(path) > os.path.getmtime(src):
        return
    V, F = read_off(src)
    for _ in range(2):
        V, F = midpoint(V, F)
    tmp = path + ".tmp"
    with open(tmp, "wb") as o:
        o.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                 "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                 % (len(V), len(F))).encode())
        o.write(b"".join(struct.pack("<3f", *v) for v in V))
        o.write(b"".join(struct.pack("<B3i", 3, *f) for f in F))
    os.replace(tmp, path)


def shown(text, what):
    """The tool's response lines for `what` ("seed", "build"): (total ms, tool ms, how, drawing ms)."""
    return [(float(m.group(1)), float(m.group(2)), m.group(3), float(m.group(4))) for m in re.finditer(
        r"%s shown (\d+) ms after the input \(tool (\d+) ms, (redraw|drawn over the last frame) (\d+) ms\)" % what,
        text)]


def test(WORK):
    t_start = time.time()
    src = os.path.join(MESHES, "bunny00.off")
    if not check(os.path.exists(src), "the bunny scan is there (%s)" % os.path.normpath(src)):
        return
    cached = os.path.join(os.path.dirname(WORK), "bunny00_x16.ply")
    subdivided_bunny(src, cached)
    mesh = os.path.join(WORK, "bunny00_x16.ply")  # its session (sidecar) is this run's only
    shutil.copy(cached, mesh)
    strict = os.environ.get("GS_LARGE_GUI_STRICT", "1") != "0"
    auto = os.path.join(WORK, "auto.json")

    t0 = time.time()
    with g.MeshLab(mesh, "large") as ml:
        if not check(ml.start_tool(), "the tool starts on the 1.2M-face bunny"):
            return
        log("mesh made/loaded and tool started in %.1f s (MeshLab %.1f s)" % (time.time() - t_start, time.time() - t0))
        # MeshLab may still be busy with the 1.2M faces when the window is sized: size it again,
        # then focus the view (a click beside the bunny places nothing; Esc twice resumes the
        # tool if that click suspended it, as in host_edit_gui_bunny)
        xdo("windowmove", ml.win, 0, 0)
        xdo("windowsize", ml.win, 1600, 1000)
        time.sleep(1.5)
        img = Image(g.screenshot("00_started.png"))
        x0, y0, x1, y1 = g.gl_box(img)  # the 3D view, as the tool's Log says
        xdo("mousemove", x0 + 20, y0 + 50, "click", 1)
        for _ in range(2):
            time.sleep(0.3)
            xdo("key", "Escape")
        time.sleep(1.0)
        # four seeds across the bunny's body, on a row through the middle of the view: the open
        # snake between them has about the 92 samples
        right = x1
        y = 560
        a, b = g.longest_run([g.is_mesh(img.px(x, y)) for x in range(x0, right)])
        a, b = a + x0, b + x0
        if not check(b - a > 100, "the bunny is in the view (%d px wide on row %d)" % (b - a, y)):
            return
        for f in (0.25, 0.42, 0.58, 0.75):
            x = int(a + f * (b - a))
            n = len(shown(ml.log_text(), "seed"))
            xdo("mousemove", x, 560, "click", 1)
            wait_for(lambda: len(shown(ml.log_text(), "seed")) > n, 20, 0.05)
        seeds = shown(ml.log_text(), "seed")
        for i, s in enumerate(seeds):
            log("click %d: seed shown after %.0f ms (tool %.0f ms, %s %.0f ms)" % ((i + 1,) + s))
        if not check(len(seeds) == 4, "four clicks on the bunny place four seeds (%d)" % len(seeds)):
            return
        green = Image(g.screenshot("01_seeds.png")).count((0, 230, 0), (x0, y - 40, x1, y + 40))
        check(green >= 4 * 20, "the four seeds are on screen (%d green pixels)" % green)
        xdo("key", "Return")
        built = wait_for(lambda: (lambda j: j if j and samples(j) else None)(snakes_of(auto)), 30)
        if not check(bool(built), "Enter builds an open snake from the seeds"):
            return
        b = wait_for(lambda: shown(ml.log_text(), "build"), 10)
        n = len(samples(built)[0]["samples"])
        check(60 <= n <= 200, "the snake has about the issue's 92 samples (%d)" % n)
        g.screenshot("02_built.png")
        if not check(bool(b), "the tool logs when the built snake is shown"):
            return
        log("build: %d samples, shown after %.0f ms (tool %.0f ms, %s %.0f ms)" % ((n,) + b[0]))
        med = statistics.median(s[0] for s in seeds)
        log("median click-to-seed %.0f ms (first click %.0f ms), build %.0f ms; total test %.1f s" % (
            med, seeds[0][0], b[0][0], time.time() - t_start))
        if strict:
            check(med <= CLICK_MS, "median click shows its seed within %d ms (%.0f ms)" % (CLICK_MS, med))
            check(max(s[0] for s in seeds) <= 3 * CLICK_MS, "every click within %d ms" % (3 * CLICK_MS))
            check(b[0][0] <= BUILD_MS, "Build shows the snake within %d ms (%.0f ms)" % (BUILD_MS, b[0][0]))


if __name__ == "__main__":
    g.main("edit_gui_large", test)
