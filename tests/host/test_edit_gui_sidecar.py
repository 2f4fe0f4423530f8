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
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.environ.get("GS_DATA_DIR", os.path.join(HERE, "..", "..", "data"))
WORK = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "..", "build", "test-artifacts",
                                                                         "edit_gui_sidecar"))
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
    subprocess.run(["import", "-window", "root", os.path.join(WORK, name)], check=False)


def red_pixels(png, x, y, w, h):
    """Pixels of the error text colour (#b00000, anti-aliased) in a box of the screenshot."""
    raw = subprocess.run(["convert", png, "-crop", "%dx%d+%d+%d" % (w, h, x, y), "+repage", "-alpha", "off",
                          "-depth", "8", "rgb:-"], capture_output=True).stdout
    return sum(1 for i in range(0, len(raw) - 2, 3) if raw[i] > 120 and raw[i + 1] < 70 and raw[i + 2] < 70)


def read_bytes(p):
    with open(p, "rb") as f:
        return f.read()


def main():
    if os.path.isdir(WORK):
        shutil.rmtree(WORK)
    os.makedirs(WORK)
    mesh = os.path.join(WORK, "icocube.ply")
    shutil.copy(os.path.join(DATA, "icocube.ply"), mesh)
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

    env = dict(os.environ)
    env["LIBGL_ALWAYS_SOFTWARE"] = "1"
    env["XDG_CONFIG_HOME"] = os.path.join(WORK, "config")
    env["XDG_RUNTIME_DIR"] = os.path.join(WORK, "runtime")
    os.makedirs(env["XDG_RUNTIME_DIR"], mode=0o700, exist_ok=True)
    logpath = os.path.join(WORK, "meshlab.log")
    logf = open(logpath, "w")
    p = subprocess.Popen(["meshlab", mesh], stdout=logf, stderr=subprocess.STDOUT, env=env, start_new_session=True)

    def log_text():
        logf.flush()
        return open(logpath, errors="replace").read()

    try:
        win = None
        for _ in range(120):
            time.sleep(0.5)
            ids = xdo("search", "--name", "MeshLab 20").split()
            if ids:
                win = ids[-1]
                break
        if not check(win is not None, "MeshLab opens the mesh"):
            return 1
        time.sleep(2)
        xdo("windowmove", win, 0, 0)
        xdo("windowsize", win, 1280, 1000)
        time.sleep(2)
        xdo("mousemove", 70, 10, "click", 1)  # Edit menu > Geometric Snake (as in test_edit_gui.py)
        time.sleep(1)
        xdo("mousemove", 141, 84, "click", 1)
        started = False
        for _ in range(20):
            time.sleep(0.5)
            if "Started Mode Geometric Snake" in log_text():
                started = True
                break
        if not check(started, "the tool starts"):
            return 1
        time.sleep(1)
        screenshot("01_started.png")
        check(read_bytes(sidecar) == before, "starting the tool leaves the truncated sidecar as it was")
        # the Log (MeshLab echoes it as "LOG: <level> <text>"): a warning that names the kept file
        # and the recovery file
        m = re.search(r"LOG: 1 Geometric snake: (.*kept unchanged; this session is saved to (\S+)\.)\n", log_text())
        check(bool(m), "the Log warns that the sidecar is kept and names the recovery file (%s)" % (
            m.group(1) if m else "no such line"))
        if m:
            check(re.fullmatch(re.escape(mesh) + r"\.snakes\.recovered-\d{8}-\d{6}(-\d+)?\.json", m.group(2)) is not None,
                  "the Log names <mesh>.snakes.recovered-<time>.json (%s)" % os.path.basename(m.group(2)))
        # the status line at the top of the panel shows the warning in red (error style)
        pm = re.search(r"panel docked in MeshLab's main window at (-?\d+),(-?\d+) size (\d+)x(\d+)", log_text())
        if check(bool(pm), "the panel is docked (its Log line)"):
            px, py, pw = int(pm.group(1)), int(pm.group(2)), int(pm.group(3))
            reds = red_pixels(os.path.join(WORK, "01_started.png"), px, py + 20, pw, 120)
            check(reds > 40, "the panel's status line shows the warning in red (%d red pixels)" % reds)

        xdo("mousemove", 425, 465, "click", 1)  # a seed on the cube (middle of the 3D view)
        time.sleep(2)
        screenshot("02_seed.png")
        xdo("mousemove", 70, 10, "click", 1)  # the same menu entry again ends the tool (it saves)
        time.sleep(1)
        xdo("mousemove", 141, 84, "click", 1)
        time.sleep(3)
        screenshot("03_ended.png")
    finally:
        try:
            os.killpg(p.pid, signal.SIGTERM)
        except ProcessLookupError:
            pass
        try:
            p.wait(10)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(10)

    check(read_bytes(sidecar) == before, "the truncated sidecar is unchanged byte for byte")
    check(read_bytes(sidecar + ".bak") == bak_before, "the old .bak file is not replaced")
    rec = sorted(glob.glob(mesh + ".snakes.recovered-*.json"))
    if check(len(rec) == 1, "one recovery file next to the mesh (%s)" % [os.path.basename(r) for r in rec]):
        j = json.load(open(rec[0]))
        check(j.get("format") == "geometric-snake-session", "the recovery file is a session")
        check(len(j.get("seeds", [])) == 1, "it holds the placed seed (%d seeds)" % len(j.get("seeds", [])))
    log("artifacts in " + WORK)
    if failures:
        log("%d check(s) failed" % len(failures))
        return 1
    log("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
