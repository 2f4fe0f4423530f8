#!/usr/bin/env python3
"""End-to-end GUI test of the Geometric Snake edit tool in the real MeshLab.

Run under an X server (xvfb-run -a -s "-screen 0 1280x1024x24" python3 test_edit_gui.py ...):
opens data/icocube.ply (cube [-1,1]^3) in MeshLab, starts the tool from the Edit menu,
clicks four seeds two edge lengths below the top edge of the front face, closes them
(Enter), runs the snake (R) and checks from the exported JSON that it converged onto the
cube edge; then drags a sample away and pins it, runs again and checks that the pin held;
checks the snake colour in a screenshot; kills MeshLab (a crash) and checks that the tool
restores the snake from the sidecar file <mesh>.snakes.json when started again.

The tool writes its JSON after every change to $GS_SNAKE_AUTOEXPORT (a hook for this test).
Artifacts (screenshots, JSON, MeshLab log) go to the work folder (first argument).
"""
import json
import math
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.environ.get("GS_DATA_DIR", os.path.join(HERE, "..", "..", "data"))
WORK = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "..", "build", "test-artifacts", "edit_gui"))
MAGENTA = (255, 0, 255)  # the selected snake's colour (edit_geometric_snake.cpp)
failures = []


def log(*a):
    print(*a, flush=True)


def check(cond, what):
    log(("PASS " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)
    return cond


def xdo(*args):
    return subprocess.run(["xdotool"] + [str(a) for a in args], capture_output=True, text=True).stdout.strip()


def screenshot(name):
    path = os.path.join(WORK, name)
    subprocess.run(["import", "-window", "root", path], check=True)
    return path


class Image:
    """A screenshot as RGB bytes (via ImageMagick's PPM output; no numpy needed)."""

    def __init__(self, png):
        raw = subprocess.run(["convert", png, "-alpha", "off", "-depth", "8", "ppm:-"], capture_output=True, check=True).stdout
        fields, pos = [], 0
        while len(fields) < 4:  # P6 w h maxval
            while raw[pos:pos + 1].isspace():
                pos += 1
            end = pos
            while not raw[end:end + 1].isspace():
                end += 1
            fields.append(raw[pos:end])
            pos = end
        self.w, self.h = int(fields[1]), int(fields[2])
        self.data = raw[pos + 1:]

    def px(self, x, y):
        i = 3 * (y * self.w + x)
        return tuple(self.data[i:i + 3])

    def count(self, rgb, box):
        x0, y0, x1, y1 = box
        n = 0
        for y in range(y0, y1):
            row = self.data[3 * (y * self.w + x0):3 * (y * self.w + x1)]
            for i in range(0, len(row), 3):
                if abs(row[i] - rgb[0]) < 8 and abs(row[i + 1] - rgb[1]) < 8 and abs(row[i + 2] - rgb[2]) < 8:
                    n += 1
        return n


def is_mesh(p):  # light grey flat shading of the mesh (the background is a dark blue gradient)
    return p[0] > 120 and abs(p[0] - p[1]) < 12 and abs(p[1] - p[2]) < 12


# ------------------------------------------------------------------ geometry of the check
def mesh_ply(path):
    f = open(path, "rb")
    nv = nf = 0
    while True:
        l = f.readline().decode().strip()
        if l.startswith("element vertex"):
            nv = int(l.split()[2])
        if l.startswith("element face"):
            nf = int(l.split()[2])
        if l == "end_header":
            break
    V = [struct.unpack("<3f", f.read(12)) for _ in range(nv)]
    F = []
    for _ in range(nf):
        n = f.read(1)[0]
        F.append(struct.unpack("<%di" % n, f.read(4 * n)))
    return V, F


def mean_edge(V, F):
    E = set()
    for t in F:
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            E.add((min(a, b), max(a, b)))
    return sum(math.dist(V[a], V[b]) for a, b in E) / len(E)


def dist_seg(p, a, b):
    d = [b[i] - a[i] for i in range(3)]
    t = sum((p[i] - a[i]) * d[i] for i in range(3)) / sum(x * x for x in d)
    t = max(0.0, min(1.0, t))
    return math.dist(p, [a[i] + d[i] * t for i in range(3)])


def dist_cube_edges(p):
    best = 1e9
    for ax in range(3):
        u, w = (ax + 1) % 3, (ax + 2) % 3
        for s1 in (-1, 1):
            for s2 in (-1, 1):
                a, b = [0.0] * 3, [0.0] * 3
                a[ax], b[ax] = -1.0, 1.0
                a[u] = b[u] = s1
                a[w] = b[w] = s2
                best = min(best, dist_seg(p, a, b))
    return best


def closest_on_triangle(p, a, b, c):
    """Ericson, Real-Time Collision Detection 5.1.5."""
    sub = lambda u, v: (u[0] - v[0], u[1] - v[1], u[2] - v[2])
    dot = lambda u, v: u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
    lerp = lambda u, d, t: (u[0] + d[0] * t, u[1] + d[1] * t, u[2] + d[2] * t)
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        return a
    bp = sub(p, b)
    d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3:
        return b
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        return lerp(a, ab, d1 / (d1 - d3))
    cp = sub(p, c)
    d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6:
        return c
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        return lerp(a, ac, d2 / (d2 - d6))
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        return lerp(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)))
    den = 1.0 / (va + vb + vc)
    v, w = vb * den, vc * den
    return (a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w)


def edge_on_mesh(V, F, h, a, b, n=200):
    """The cube edge a-b as the mesh has it: points of the exact edge moved to their closest
    point on the mesh (its straddling triangles chamfer the edge up to about h/2 deep)."""
    cen = [tuple(sum(V[t[k]][i] for k in range(3)) / 3 for i in range(3)) for t in F]
    out = []
    for k in range(n + 1):
        q = [a[i] + (b[i] - a[i]) * (0.05 + 0.9 * k / n) for i in range(3)]
        best, bp = 1e9, None
        for t, c in zip(F, cen):
            if math.dist(c, q) > 3 * h:
                continue
            x = closest_on_triangle(q, V[t[0]], V[t[1]], V[t[2]])
            d = math.dist(x, q)
            if d < best:
                best, bp = d, x
        if bp:
            out.append(bp)
    return out


def dist_polyline(p, pl):
    return min(dist_seg(p, pl[i], pl[i + 1]) for i in range(len(pl) - 1))


def nearest_cube_edge(p):
    best, seg = 1e9, None
    for ax in range(3):
        u, w = (ax + 1) % 3, (ax + 2) % 3
        for s1 in (-1, 1):
            for s2 in (-1, 1):
                a, b = [0.0] * 3, [0.0] * 3
                a[ax], b[ax] = -1.0, 1.0
                a[u] = b[u] = s1
                a[w] = b[w] = s2
                d = dist_seg(p, a, b)
                if d < best:
                    best, seg = d, (a, b)
    return seg


def load_snakes(path):
    j = json.load(open(path))
    return j["snakes"] if "snakes" in j else [j]


def wait_json(path, pred, timeout):
    t0 = time.time()
    last = None
    while time.time() - t0 < timeout:
        try:
            s = load_snakes(path)
            last = s
            if pred(s):
                return s
        except (OSError, ValueError, KeyError):
            pass
        time.sleep(0.3)
    return last


# ------------------------------------------------------------------ MeshLab
class MeshLab:
    def __init__(self, mesh, tag):
        env = dict(os.environ)
        env["LIBGL_ALWAYS_SOFTWARE"] = "1"
        env["GS_SNAKE_AUTOEXPORT"] = os.path.join(WORK, "auto.json")
        env["XDG_CONFIG_HOME"] = os.path.join(WORK, "config")  # fresh MeshLab settings
        env["XDG_RUNTIME_DIR"] = os.path.join(WORK, "runtime")
        os.makedirs(env["XDG_RUNTIME_DIR"], mode=0o700, exist_ok=True)
        self.logpath = os.path.join(WORK, "meshlab_%s.log" % tag)
        self.logf = open(self.logpath, "w")
        self.p = subprocess.Popen(["meshlab", mesh], stdout=self.logf, stderr=subprocess.STDOUT, env=env,
                                  start_new_session=True)
        self.win = None
        for _ in range(120):
            time.sleep(0.5)
            ids = xdo("search", "--name", "MeshLab 20").split()
            if ids:
                self.win = ids[-1]
                break
        if not self.win:
            raise RuntimeError("MeshLab window did not appear")
        time.sleep(2)
        xdo("windowmove", self.win, 0, 0)
        xdo("windowsize", self.win, 1280, 1000)
        time.sleep(2)

    def log_text(self):
        self.logf.flush()
        return open(self.logpath).read()

    def start_tool(self):
        # Edit menu -> "Geometric Snake" (second entry after "Align" in Debian's MeshLab 2020.09)
        xdo("mousemove", 70, 10, "click", 1)
        time.sleep(1)
        screenshot("edit_menu.png")
        xdo("mousemove", 141, 84, "click", 1)
        for _ in range(20):
            time.sleep(0.5)
            if "Started Mode Geometric Snake" in self.log_text():
                return True
        return False

    def kill(self, sig=signal.SIGTERM):
        try:
            os.killpg(self.p.pid, sig)
        except ProcessLookupError:
            pass
        try:
            self.p.wait(10)
        except subprocess.TimeoutExpired:
            os.killpg(self.p.pid, signal.SIGKILL)
            self.p.wait(10)


def gl_box(img):
    """The GL area: left of the layer panel and above the info overlay (found by its mesh pixels)."""
    return (0, 70, 850, 860)


def longest_run(flags):
    best, start = (0, 0, -1), None
    for i, f in enumerate(flags + [False]):
        if f and start is None:
            start = i
        if not f and start is not None:
            if i - start > best[0]:
                best = (i - start, start, i - 1)
            start = None
    return best[1], best[2]


def front_face_extent(img):
    """Pixel extent of the front face (the longest runs of mesh pixels through the middle)."""
    x0, y0, x1, y1 = gl_box(img)
    ymid = (y0 + y1) // 2
    a, b = longest_run([is_mesh(img.px(x, ymid)) for x in range(x0, x1)])
    left, right = x0 + a, x0 + b
    xm = (left + right) // 2
    a, b = longest_run([is_mesh(img.px(xm, y)) for y in range(y0 + 5, y1)])
    return left, right, y0 + 5 + a, y0 + 5 + b


def magenta_y(img, x):
    x0, y0, x1, y1 = gl_box(img)
    ys = [y for y in range(y0, y1) if img.count(MAGENTA, (x, y, x + 1, y + 1))]
    return ys


def main():
    if os.path.isdir(WORK):
        shutil.rmtree(WORK)
    os.makedirs(WORK)
    mesh = os.path.join(WORK, "icocube.ply")
    src = os.path.join(DATA, "icocube.ply")
    if not os.path.exists(src):
        log("data/icocube.ply missing")
        return 1
    shutil.copy(src, mesh)
    V, F = mesh_ply(mesh)
    h = mean_edge(V, F)
    auto = os.path.join(WORK, "auto.json")
    sidecar = mesh + ".snakes.json"

    ml = MeshLab(mesh, "run1")
    try:
        check(ml.start_tool(), "the tool starts from the Edit menu")
        img = Image(screenshot("01_started.png"))
        time.sleep(1)  # the tool logs where its panel is once the main window has laid it out
        check(bool(re.search(r"panel docked in MeshLab's main window", ml.log_text())) or
              bool(xdo("search", "--name", "^Geometric Snake$")), "the Geometric Snake panel is shown")
        left, right, top, bottom = front_face_extent(img)
        hpx = (right - left) / 2.0 * h  # the front face spans 2 units
        log("front face px: x %d..%d y %d..%d, h = %.4f = %.1f px" % (left, right, top, bottom, h, hpx))

        # seeds: 2.2 edge lengths below the top edge of the front face
        ys = int(top + 2.2 * hpx)
        for f in (0.2, 0.4, 0.6, 0.8):
            xdo("mousemove", int(left + f * (right - left)), ys, "click", 1)
            time.sleep(0.4)
        screenshot("02_seeds.png")
        xdo("key", "Return")
        s = wait_json(auto, lambda s: len(s) == 1 and len(s[0]["samples"]) >= 5, 20)
        check(s is not None and len(s) == 1, "Enter builds the snake from the clicked seeds")
        if not s:
            return 1
        d0 = [dist_cube_edges(x["position"]) for x in s[0]["samples"][1:-1]]
        log("initial mean distance to the edge: %.2f h" % (sum(d0) / len(d0) / h))
        check(sum(d0) / len(d0) > 1.0 * h, "the initial snake is away from the edge (%.2f h)" % (sum(d0) / len(d0) / h))

        t0 = time.time()
        xdo("key", "r")
        s = wait_json(auto, lambda s: s[0]["stats"]["converged"], 60)
        check(s[0]["stats"]["converged"], "Run: the snake converges (%d operations, %.1f s wall, %.2f ms/op)" % (
            s[0]["stats"]["operations"], time.time() - t0, s[0]["stats"]["ms_per_operation"]))
        pos = [x["position"] for x in s[0]["samples"][1:-1]]
        d = [dist_cube_edges(p) for p in pos]
        mean_d = sum(d) / len(d)
        # The mesh's triangles straddle the exact edge and cut it like a chamfer (up to ~0.45 h
        # deep), so no curve on the mesh gets closer to the exact edge than that: the snake
        # is measured against the edge as the mesh has it (< 0.25 h mean), and against the
        # exact edge (< 0.5 h mean).
        ea, eb = nearest_cube_edge(pos[len(pos) // 2])
        onmesh = edge_on_mesh(V, F, h, ea, eb)
        dm = [dist_polyline(p, onmesh) for p in pos]
        check(sum(dm) / len(dm) < 0.25 * h,
              "converged onto the cube edge as the mesh has it: mean %.3f h, max %.3f h" % (sum(dm) / len(dm) / h, max(dm) / h))
        check(mean_d < 0.5 * h,
              "and near the exact cube edge: mean %.3f h, max %.3f h" % (mean_d / h, max(d) / h))
        img = Image(screenshot("03_converged.png"))
        n = img.count(MAGENTA, gl_box(img))
        check(n > 300, "the snake colour appears in the screenshot (%d px)" % n)

        # drag the middle sample down onto the face and pin it (Edit samples mode is on)
        xm = (left + right) // 2
        ym = magenta_y(img, xm)
        check(bool(ym), "the snake is visible at the middle column")
        if ym:
            y = ym[len(ym) // 2]
            xdo("mousemove", xm, y)
            time.sleep(0.3)
            xdo("mousedown", 1)
            for k in range(1, 11):
                xdo("mousemove", xm, int(y + k * 0.35 * hpx))
                time.sleep(0.05)
            xdo("mouseup", 1)
            s = wait_json(auto, lambda s: any(x["fixed"] for x in s[0]["samples"]), 10)
            pins = [x for x in s[0]["samples"] if x["fixed"]]
            check(len(pins) == 1, "dragging a sample pins it (%d pinned)" % len(pins))
            if pins:
                pd = dist_cube_edges(pins[0]["position"])
                check(pd > 2.0 * h, "the dragged sample moved away from the edge (%.2f h)" % (pd / h))
                pinpos = pins[0]["position"]
                xdo("key", "r")
                s = wait_json(auto, lambda s: s[0]["stats"]["converged"], 60)
                pins2 = [x for x in s[0]["samples"] if x["fixed"]]
                check(len(pins2) == 1 and math.dist(pins2[0]["position"], pinpos) < 1e-6,
                      "the pin holds exactly while the snake runs again")
                screenshot("04_dragged_pinned.png")
        # undo (Ctrl+Z) changes the snake back
        before = json.load(open(auto))
        xdo("key", "ctrl+z")
        time.sleep(1)
        after = json.load(open(auto))
        check(before != after, "Ctrl+Z undoes the last change")
        xdo("key", "ctrl+y")
        time.sleep(1.5)

        ok = os.path.exists(sidecar)
        check(ok, "the session is autosaved to %s" % os.path.basename(sidecar))
        if ok:
            sc = json.load(open(sidecar))
            check(sc.get("format") == "geometric-snake-session" and len(sc["snakes"]) == 1,
                  "the sidecar file holds the snake")
            check(any(x["fixed"] for x in sc["snakes"][0]["samples"]), "the sidecar file keeps the pin")
    finally:
        ml.kill(signal.SIGKILL)  # like a crash: no chance to save at exit

    # ---- restart: the tool restores the snake from the sidecar file
    time.sleep(1)
    if os.path.exists(auto):
        os.remove(auto)
    ml = MeshLab(mesh, "run2")
    try:
        check(ml.start_tool(), "the tool starts again after the crash")
        time.sleep(1.5)
        img = Image(screenshot("05_restored.png"))
        n = img.count(MAGENTA, gl_box(img))
        check(n > 300, "the snake is restored and drawn after restarting MeshLab (%d px)" % n)
        xdo("mousemove", 300, 600, "click", 1)  # focus the 3D view (a click away from the snake does nothing)
        time.sleep(0.5)
        xdo("key", "space")  # one step: the auto-export shows the restored snake
        s = wait_json(auto, lambda s: len(s) == 1, 10)
        if s:
            check(any(x["fixed"] for x in s[0]["samples"]), "the restored snake keeps its pin")
    finally:
        ml.kill()

    log("artifacts in " + WORK)
    if failures:
        log("%d check(s) failed" % len(failures))
        return 1
    log("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
