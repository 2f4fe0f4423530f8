"""Shared helpers of the GUI tests (tests/host/test_edit_gui*.py): the real MeshLab under an X
server (Xvfb), driven by xdotool and photographed with ImageMagick's `import`.

- checks and logging: check() records failures, finish() prints the verdict and the exit status;
- the X server: xdo(), screenshot(), Image (a screenshot's pixels), window_geometry();
- MeshLab: the MeshLab class starts it on a mesh with fresh settings and a Log file, starts the
  Geometric Snake tool from the Edit menu; its 3D view and panel positions (the tool's Log lines)
  in the 1600x1000 window (narrower on a narrower screen);
- the tool's JSON (written after every change to $GS_SNAKE_AUTOEXPORT) and its Log lines;
- the cube's geometry (data/icocube.ply, [-1,1]^3): distances to its edges, as the mesh has them.

A test script is a function test(work) run by main(name, test), which sets its work folder and
exits with the verdict; MeshLab runs in a `with MeshLab(...) as ml:` block, which kills it.
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
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.environ.get("GS_DATA_DIR", os.path.join(HERE, "..", "..", "data"))
WORK = None  # the test's work folder (artifacts: screenshots, JSON, MeshLab's Log); set by start()
VIEW = None  # the 3D view (x, y, w, h) on screen, from the tool's Log once it has started
MAGENTA = (255, 0, 255)  # the selected snake's colour (edit_geometric_snake.cpp)
failures = []


def start(name):
    """The work folder (the first argument, else build/test-artifacts/<name>), emptied."""
    global WORK
    WORK = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "..", "build",
                                                                                "test-artifacts", name))
    if os.path.isdir(WORK):
        shutil.rmtree(WORK)
    os.makedirs(WORK)
    return WORK


def finish():
    """Prints the verdict; the exit status of the test script."""
    log("artifacts in " + WORK)
    if failures:
        log("%d check(s) failed" % len(failures))
        return 1
    log("all checks passed")
    return 0


def main(name, test):
    """A GUI test script's main: test(work) in the work folder start(name), then the verdict
    (finish) as the exit status. A test returns early only after a failed check; an exception
    is a failed check too."""
    work = start(name)
    try:
        test(work)
    except Exception as e:  # noqa: BLE001 (any error of the test is its failure, with the artifacts)
        traceback.print_exc()
        check(False, "the test runs to its end (%s: %s)" % (type(e).__name__, e))
    sys.exit(finish())


def copy_data(name):
    """A copy of data/<name> in the work folder (the tests never write next to the repo's data)."""
    path = os.path.join(WORK, name)
    shutil.copy(os.path.join(DATA, name), path)
    return path


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


def cube_edges():
    """The 12 edges of the cube [-1, 1]^3 (data/icocube.ply), as point pairs."""
    for ax in range(3):
        u, w = (ax + 1) % 3, (ax + 2) % 3
        for s1 in (-1, 1):
            for s2 in (-1, 1):
                a, b = [0.0] * 3, [0.0] * 3
                a[ax], b[ax] = -1.0, 1.0
                a[u] = b[u] = s1
                a[w] = b[w] = s2
                yield a, b


def dist_cube_edges(p):
    return min(dist_seg(p, a, b) for a, b in cube_edges())


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
    return min(cube_edges(), key=lambda e: dist_seg(p, *e))


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
    """MeshLab on `mesh`, its window at 0,0 and 1600x1000, fresh settings, its Log (stdout) in
    meshlab_<tag>.log. With `autoexport` the tool writes its JSON to WORK/auto.json after every
    change (the test hook $GS_SNAKE_AUTOEXPORT). A context manager: the end of the `with` block
    kills MeshLab with signal `kill` (SIGKILL: like a crash, no chance to save at exit)."""

    def __init__(self, mesh, tag, autoexport=True, kill=signal.SIGTERM):
        self.kill_signal = kill
        env = dict(os.environ)
        env["LIBGL_ALWAYS_SOFTWARE"] = "1"
        if autoexport:
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
            self.kill()
            raise RuntimeError("MeshLab window did not appear")
        time.sleep(2)
        xdo("windowmove", self.win, 0, 0)
        screen = re.match(r"(\d+) (\d+)", xdo("getdisplaygeometry"))
        xdo("windowsize", self.win, min(1600, int(screen.group(1))) if screen else 1280, 1000)
        time.sleep(2)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.kill(self.kill_signal)
        return False

    def log_text(self):
        self.logf.flush()
        return open(self.logpath, errors="replace").read()

    def start_tool(self):
        # Edit menu -> "Geometric Snake" (second entry after "Align" in Debian's MeshLab 2020.09)
        xdo("mousemove", 70, 10, "click", 1)
        time.sleep(1)
        screenshot("edit_menu.png")
        xdo("mousemove", 141, 84, "click", 1)
        global VIEW
        for _ in range(20):
            time.sleep(0.5)
            if "Started Mode Geometric Snake" in self.log_text():
                # where the 3D view is, once the main window has laid the panel out
                m = wait_for(lambda: list(re.finditer(r"3D view at (-?\d+),(-?\d+) size (\d+)x(\d+)", self.log_text())), 3)
                if m:
                    VIEW = tuple(int(m[-1].group(k)) for k in range(1, 5))
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
    """The 3D view above MeshLab's info overlay (~100 px high), as the tool's Log says; else
    the view of a 1280x1000 window with the panel as a tab on the right (before issue 37)."""
    if VIEW:
        x, y, w, h = VIEW
        return (max(0, x), max(0, y), min(img.w, x + w), min(img.h, y + h - 105))
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


def sample_near(img, x, y, r=25):
    """The nearest sample marker (a white square on the curve) to (x, y) within r px, else (x, y):
    a press starts a drag only on a sample (the tool picks the nearest one within 20 px)."""
    best = None
    for yy in range(max(0, y - r), min(img.h, y + r + 1)):
        for xx in range(max(0, x - r), min(img.w, x + r + 1)):
            if min(img.px(xx, yy)) >= 250:
                d = (xx - x) ** 2 + (yy - y) ** 2
                if best is None or d < best[0]:
                    best = (d, xx, yy)
    return (best[1], best[2]) if best else (x, y)


def snake_rows(img, x):
    """The selected snake's rows at column x, or beside it (a sample's marker may cover the curve)."""
    return next((ys for ys in (magenta_y(img, x + dx) for dx in (0, 6, -6, 12, -12)) if ys), [])


# ------------------------------------------------------------------ the tool's JSON and Log
def snakes_of(path):
    try:
        return json.load(open(path))
    except (OSError, ValueError):
        return None


def wait_for(pred, timeout, step=0.2):
    t0 = time.time()
    while time.time() - t0 < timeout:
        v = pred()
        if v:
            return v
        time.sleep(step)
    return pred()


def samples(j):
    """The snakes of an exported JSON (a session or one snake)."""
    return j["snakes"] if "snakes" in j else [j]


def changed(path, before, timeout=5):
    """The JSON at `path` once it differs from `before` (None after `timeout` s)."""
    return wait_for(lambda: (lambda j: j if j and j != before else None)(snakes_of(path)), timeout)


def build_from_clicks(auto, left, right, y, min_samples=1, timeout=20):
    """Clicks four seeds along row y across the face [left, right] and presses Enter: the built
    snake's JSON (auto-exported to `auto`) once it has `min_samples` samples, else None."""
    for f in (0.2, 0.4, 0.6, 0.8):
        xdo("mousemove", int(left + f * (right - left)), int(y), "click", 1)
        time.sleep(0.4)
    xdo("key", "Return")
    return wait_for(lambda: (lambda j: j if j and samples(j) and len(samples(j)[0]["samples"]) >= min_samples else None)(
        snakes_of(auto)), timeout)


def start_on_front_face(ml, shot):
    """Starts the tool and finds the cube's front face on screenshot `shot`: (left, right, top,
    bottom) in pixels, or None if the tool did not start."""
    if not check(ml.start_tool(), "the tool starts from the Edit menu"):
        return None
    time.sleep(1.0)
    return front_face_extent(Image(screenshot(shot)))


def curve_state(j):
    """What the user sees of the snakes: samples (positions, pins), the curves, the counters."""
    return [(x["closed"], x["samples"], x["polyline"], x["stats"]["operations"], x["stats"]["converged"])
            for x in samples(j)]


def focus_view():
    """Focuses the 3D view with a click away from the mesh (bottom of the view); Esc twice
    suspends and resumes the tool in case the click started something."""
    time.sleep(1.0)
    xdo("mousemove", 400, 950, "click", 1)
    for _ in range(2):
        time.sleep(0.3)
        xdo("key", "Escape")
    time.sleep(0.3)


def closed_snake(path):
    """The tool's JSON at `path` once it holds a closed snake, else None."""
    j = snakes_of(path)
    return j if j and samples(j) and samples(j)[0]["closed"] else None


def run_lines(text):
    """The tool's Log lines of finished Runs: (state, operations, compute s, wall s)."""
    return [(m.group(1), int(m.group(2)), float(m.group(3)), float(m.group(4))) for m in re.finditer(
        r"Run (converged|stopped) after (\d+) operations: compute ([0-9.]+) s, wall ([0-9.]+) s", text)]


def panel_geometry(text):
    """Where the tool says its panel is (its Log line): (docked?, x, y, w, h) of the last one, or None."""
    m = list(re.finditer(r"panel (docked|floating) in MeshLab's main window at (-?\d+),(-?\d+) size (\d+)x(\d+)", text))
    if not m:
        return None
    m = m[-1]
    return (m.group(1) == "docked",) + tuple(int(m.group(k)) for k in range(2, 6))


def layer_dialog(text):
    """Where the tool says MeshLab's layer dialog (with the Log) is (its Log line): (x, y, w, h,
    "visible" or not) of the last one, or None."""
    m = list(re.finditer(r"layer dialog \(with the Log\) at (-?\d+),(-?\d+) size (\d+)x(\d+), (\w+)", text))
    return tuple(int(m[-1].group(k)) for k in range(1, 5)) + (m[-1].group(5),) if m else None


def panel_and_layer_dialog(ml, timeout=5):
    """The docked panel's box and the layer dialog's from the tool's Log lines, checked and logged:
    (panel box, layer dialog box, the layer dialog's visibility), or None."""
    lm = wait_for(lambda: layer_dialog(ml.log_text()), timeout)
    pg = panel_geometry(ml.log_text())
    if not check(bool(pg) and pg[0] and bool(lm) and VIEW, "the tool logs the panel, view and layer dialog boxes"):
        return None
    log("panel %s, view %s, layer dialog %s (%s)" % (pg[1:], VIEW, lm[:4], lm[4]))
    return pg[1:], lm[:4], lm[4]


def overlap(a, b):
    """Whether boxes a and b (x, y, w, h) overlap."""
    ax, ay, aw, ah = a
    bx, by, bw, bh = b
    return ax < bx + bw and bx < ax + aw and ay < by + bh and by < ay + ah


def panel_state_reader(path):
    """Sets $GS_SNAKE_PANEL_STATE to `path` (the tool then writes what its panel shows there on every
    change; set before MeshLab starts) and returns panel(pred, timeout): the state once pred
    holds within timeout seconds, else {}."""
    os.environ["GS_SNAKE_PANEL_STATE"] = path

    def panel(pred=lambda s: True, timeout=3):
        def read():
            try:
                s = json.load(open(path))
            except (OSError, ValueError):
                return None
            return s if pred(s) else None
        return wait_for(read, timeout) or read() or {}
    return panel


def window_geometry(win):
    out = xdo("getwindowgeometry", win)
    pos = re.search(r"Position: (-?\d+),(-?\d+)", out)
    size = re.search(r"Geometry: (\d+)x(\d+)", out)
    return (int(pos.group(1)), int(pos.group(2)), int(size.group(1)), int(size.group(2))) if pos and size else None


def red_pixels(png, x, y, w, h):
    """Pixels of the error text colour (#b00000, anti-aliased) in a box of a screenshot."""
    raw = subprocess.run(["convert", png, "-crop", "%dx%d+%d+%d" % (w, h, x, y), "+repage", "-alpha", "off",
                          "-depth", "8", "rgb:-"], capture_output=True).stdout
    return sum(1 for i in range(0, len(raw) - 2, 3) if raw[i] > 120 and raw[i + 1] < 70 and raw[i + 2] < 70)


def read_bytes(p):
    with open(p, "rb") as f:
        return f.read()


def save_dialog(title, path, confirm_replace=False):
    """Types `path` into a Qt file dialog titled `title` and accepts it."""
    win = wait_for(lambda: xdo("search", "--name", title).split(), 10)
    if not win:
        return False
    time.sleep(0.8)
    xdo("key", "ctrl+a")
    xdo("type", "--delay", "5", path)
    time.sleep(0.3)
    xdo("key", "Return")
    if confirm_replace:  # "... already exists. Do you want to replace it?"
        time.sleep(1.0)
        screenshot("replace_%s.png" % os.path.basename(path))
        xdo("key", "alt+y")
    return True


def drag(x, y, dx, dy, steps, pause=0.05):
    """A left-button drag from (x, y) by (dx, dy) in `steps` mouse moves (one motion event each)."""
    xdo("mousemove", x, y)
    time.sleep(0.3)
    xdo("mousedown", 1)
    for k in range(1, steps + 1):
        xdo("mousemove", int(round(x + dx * k / steps)), int(round(y + dy * k / steps)))
        time.sleep(pause)
    xdo("mouseup", 1)


def session_with_seeds(src, seeds, energy=None):
    """A copy of mesh `src` (an OFF file) in the work folder with a session file next to it that
    holds `seeds` (vertex indices) and, if given, the energy settings (e.g. {"type": 4,
    "smoothing": 2}), as the tool saves them: the tool restores both when it starts. The copy's path."""
    mesh = os.path.join(WORK, os.path.basename(src))
    shutil.copyfile(src, mesh)
    head = open(mesh).read(200).split()
    s = {"format": "geometric-snake-session", "version": 1,
         "mesh": {"vertices": int(head[1]), "faces": int(head[2])}, "seeds": seeds, "snakes": []}
    if energy:
        s["energy"] = energy
    json.dump(s, open(mesh + ".snakes.json", "w"))
    return mesh


def run_until_logged(ml, name, timeout):
    """Presses R and waits for the tool's Run line in the Log (at most `timeout` s), then
    photographs the screen (<name>.png): (the run_lines() of the Log, seconds waited)."""
    t0 = time.time()
    xdo("key", "r")
    lines = wait_for(lambda: run_lines(ml.log_text()), timeout)
    waited = time.time() - t0
    time.sleep(1.0)
    screenshot("%s.png" % name)
    return lines, waited


def stopped_snake(auto, timeout=10):
    """The tool's JSON at `auto` once its snake's stats.stop says why its Run ended, else None."""
    return wait_for(lambda: (lambda s: s if s and samples(s) and samples(s)[0].get("stats", {}).get("stop") not in
                             (None, "running") else None)(snakes_of(auto)), timeout)


def build_closed_from_session(ml, name, auto, what="seeds"):
    """Starts the tool (it restores the session's seeds), focuses the view and presses Shift+Enter:
    the tool's JSON (auto-exported to `auto`) once it holds the closed snake, else None (a check
    failed)."""
    if os.path.exists(auto):
        os.remove(auto)
    if not check(ml.start_tool(), "%s: the tool starts with the restored %s" % (name, what)):
        return None
    focus_view()
    xdo("key", "shift+Return")
    built = wait_for(lambda: closed_snake(auto), 30)
    return built if check(bool(built), "%s: Shift+Enter builds a closed snake" % name) else None


def status_reds(text, name):
    """Red pixels (the stop colour) in the panel's status line on the screenshot <name>.png, the
    panel's place read from the Log `text`; None if the Log does not give it (a check failed)."""
    pg = panel_geometry(text)
    if not check(bool(pg), "%s: the panel's place is in the Log" % name):
        return None
    _, px, py, pw, ph = pg
    return red_pixels(os.path.join(WORK, "%s.png" % name), px, py + 20, pw, 120)


def panel_widget(panel, name, timeout=3):
    """The box (x, y, w, h) of the panel's widget `name` (a button's text, "section <title>" for a
    section's header, or a field's name: "Max operations", "Time limit") as the panel-state hook
    last wrote it (`panel` from panel_state_reader), once it is shown; else None."""
    s = panel(lambda s: s.get("widgets", {}).get(name, {}).get("visible"), timeout)
    w = s.get("widgets", {}).get(name)
    return (w["x"], w["y"], w["w"], w["h"]) if w and w.get("visible") else None


def set_section(panel, title, want_open):
    """Opens or closes the panel's section `title` by a click on its header: True once it is as asked."""
    name = "section " + title
    s = panel(lambda s: name in s.get("widgets", {}))
    w = s.get("widgets", {}).get(name)
    if not w:
        return False
    if w.get("checked") != want_open:
        xdo("mousemove", w["x"] + w["w"] // 4, w["y"] + w["h"] // 2, "click", 1)
    return bool(panel(lambda s: s.get("widgets", {}).get(name, {}).get("checked") == want_open))


def click_widget(panel, name):
    """Clicks the middle of the panel's widget `name` (see panel_widget): False if it is not shown."""
    b = panel_widget(panel, name)
    if b:
        xdo("mousemove", b[0] + b[2] // 2, b[1] + b[3] // 2, "click", 1)
    return bool(b)


def type_into(panel, name, text):
    """Types `text` into the panel's field `name` as a user does: a click in it, Ctrl+A, the text,
    Tab to leave it. False if the field is not shown."""
    if not click_widget(panel, name):
        return False
    time.sleep(0.3)
    xdo("key", "ctrl+a")
    xdo("type", "--delay", "50", text)
    xdo("key", "Tab")
    time.sleep(0.5)
    return True
