#!/usr/bin/env python3
"""Inside the Debian 13 root, under Xvfb: MeshLab 2022.02's GUI starts with the installed
plugins, shows no plugin-loading error, and the Geometric Snake edit tool starts on a mesh
(GS_SNAKE_AUTOSTART=1 triggers its action as soon as MeshLab has the mesh; MeshLab logs
"Started Mode Geometric Snake" only when the tool's startEdit succeeded).

    xvfb-run -a -s "-screen 0 1280x1024x24" python3 gui_in_root.py MESH WORK_DIR
"""
import os
import subprocess
import sys
import time

mesh, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
failures = []


def check(cond, what):
    print(("PASS " if cond else "FAIL ") + what, flush=True)
    if not cond:
        failures.append(what)


def windows(name):
    out = subprocess.run(["xdotool", "search", "--name", name], capture_output=True, text=True).stdout
    return out.split()


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
        main_window = main_window or windows("MeshLab 2022")
        text = open(logpath, errors="replace").read()
        if "Started Mode Geometric Snake" in text or p.poll() is not None:
            started = "Started Mode Geometric Snake" in text
            break
    time.sleep(1)
    check(p.poll() is None, "MeshLab 2022.02 is running")
    check(bool(main_window), "MeshLab's main window appeared (title 'MeshLab 2022.02...')")
    check(not windows("Error while loading plugins"), "no 'Error while loading plugins' dialog (every plugin loaded)")
    check(started, "the Geometric Snake edit tool started on %s ('Started Mode Geometric Snake')" % os.path.basename(mesh))
    # the panel docks in MeshLab's main window (and says where in the Log), or floats on its own
    text = open(logpath, errors="replace").read()
    check("Geometric snake: panel" in text or bool(windows("^Geometric Snake$")), "the tool's panel is shown")
    p.terminate()
    try:
        p.wait(10)
    except subprocess.TimeoutExpired:
        p.kill()
        p.wait()
if failures:
    print("--- MeshLab output (%s)" % logpath)
    print(open(logpath, errors="replace").read()[-4000:])
sys.exit(1 if failures else 0)
