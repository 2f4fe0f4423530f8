#!/usr/bin/env python3
"""Cutting along snakes on real part boundaries (issue 34), with the geometric-snake program.

For each part of a person's segmentation (Princeton benchmark, ../shared/data/segmentation)
bounded by one loop and smaller than half the mesh:
  - the part's boundary edges as a curve file -> `geometric-snake cut`: the selected faces must
    be exactly the part's (reported as mismatching faces, expected 0);
  - a closed snake seeded on --seeds vertices (default 6) evenly along that boundary -> `geometric-snake cut --mode
    select-only` (whole faces by their centroid's side): the intersection over union (by area)
    of the selected part with the person's part.

  usage: scripts/eval_cut.py [--cli build/cli/geometric-snake] [--ids 181,3] [--out FOLDER]
         [--curve-only ID:LABEL:OUT.json]   (writes one part's boundary curve and stops)
Prints one line per part and a summary (median IoU).
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "host"))
import mlhost  # noqa: E402

SEG = os.path.join(HERE, "..", "..", "shared", "data", "segmentation")


def read_off(path):
    with open(path) as f:
        tok = f.read().split()
    assert tok[0] == "OFF"
    nv, nf = int(tok[1]), int(tok[2])
    p = 4
    verts = [tuple(float(x) for x in tok[p + 3 * i:p + 3 * i + 3]) for i in range(nv)]
    p += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(tok[p])
        faces.append(tuple(int(x) for x in tok[p + 1:p + 1 + n]))
        p += 1 + n
    return verts, faces


def area(verts, f):
    a, b, c = (verts[i] for i in f)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    w = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    return 0.5 * sum(x * x for x in w) ** 0.5


def boundary_loops(faces, label, lab):
    """Directed boundary edges of part `lab` (along its faces' order) chained into loops of
    (vertex, face holding it, corner)."""
    edges = {}
    for fi, f in enumerate(faces):
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            edges.setdefault((min(a, b), max(a, b)), []).append((fi, k))
    nxt = {}
    for (a, b), fs in edges.items():
        if len(fs) != 2:
            continue
        (f0, k0), (f1, k1) = fs
        if (label[f0] == lab) == (label[f1] == lab):
            continue
        fi, k = (f0, k0) if label[f0] == lab else (f1, k1)
        nxt[faces[fi][k]] = (faces[fi][(k + 1) % 3], fi, k)
    loops, used = [], set()
    for s in nxt:
        if s in used:
            continue
        loop, v = [], s
        while v not in used and v in nxt:
            used.add(v)
            loop.append((v, nxt[v][1], nxt[v][2]))
            v = nxt[v][0]
        loops.append(loop)
    return loops


def curve_json(verts, loop):
    samples = []
    for v, f, k in loop:
        b = [0.0, 0.0, 0.0]
        b[k] = 1.0
        samples.append({"face": f, "bary": b, "position": list(verts[v])})
    return {"closed": True, "samples": samples}


def run(cmd):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=600)
    return p.returncode, p.stdout.decode(), p.stderr.decode()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default=os.path.join(HERE, "..", "build", "cli", "geometric-snake"))
    ap.add_argument("--ids", default="181,3")
    ap.add_argument("--out", default=None)
    ap.add_argument("--curve-only", default=None)
    ap.add_argument("--snake-args", default="", help="extra options of geometric-snake snake, e.g. \"--balloon 0.2\"")
    ap.add_argument("--seeds", type=int, default=6, help="seed vertices per snake, evenly along the boundary")
    a = ap.parse_args()
    work = a.out or tempfile.mkdtemp(prefix="gs-eval-cut-")
    os.makedirs(work, exist_ok=True)
    if a.curve_only:
        mid, lab, out = a.curve_only.split(":", 2)
        verts, faces = read_off(os.path.join(SEG, "off", mid + ".off"))
        with open(os.path.join(SEG, "seg", mid, mid + "_0.seg")) as f:
            label = [int(x) for x in f.read().split()]
        loops = boundary_loops(faces, label, int(lab))
        with open(out, "w") as f:
            json.dump(curve_json(verts, loops[0]), f)
        return 0
    ious, exact_bad, tested = [], 0, 0
    for mid in a.ids.split(","):
        mesh = os.path.join(SEG, "off", mid + ".off")
        verts, faces = read_off(mesh)
        with open(os.path.join(SEG, "seg", mid, mid + "_0.seg")) as f:
            label = [int(x) for x in f.read().split()]
        fa = [area(verts, f) for f in faces]
        total = sum(fa)
        for lab in sorted(set(label)):
            part = sum(x for x, l in zip(fa, label) if l == lab)
            loops = boundary_loops(faces, label, lab)
            if len(loops) != 1 or len(loops[0]) < 8 or part > total / 2:
                continue
            loop = loops[0]
            tested += 1
            # 1. the human boundary as the curve: the selection must be exactly the part
            cf = os.path.join(work, "m%s_l%d_boundary.json" % (mid, lab))
            with open(cf, "w") as f:
                json.dump(curve_json(verts, loop), f)
            out = os.path.join(work, "m%s_l%d_boundary.ply" % (mid, lab))
            rc, so, se = run([a.cli, "cut", mesh, "--curve", cf, "-o", out, "-q"])
            if rc != 0:
                print("mesh %s part %d: boundary cut failed: %s" % (mid, lab, se.strip()))
                exact_bad += 1
                continue
            q = [f["quality"] for f in mlhost.read_ply(out).faces]
            bad = sum((q[i] == 1) != (label[i] == lab) for i in range(len(faces)))
            exact_bad += bad > 0
            # 2. a snake seeded on SEEDS vertices of the boundary, then cut along it
            seeds = ",".join(str(loop[len(loop) * i // a.seeds][0]) for i in range(a.seeds))
            sj = os.path.join(work, "m%s_l%d_snake.json" % (mid, lab))
            rc, so, se = run([a.cli, "snake", mesh, "--seeds", seeds, "--closed", "-o", sj, "-q"] + a.snake_args.split())
            if rc != 0:
                print("mesh %s part %d: snake failed: %s" % (mid, lab, se.strip()))
                continue
            out = os.path.join(work, "m%s_l%d_snake.ply" % (mid, lab))
            rc, so, se = run([a.cli, "cut", mesh, "--curve", sj, "--mode", "select-only", "-o", out, "-q"])
            if rc != 0:
                print("mesh %s part %d: snake cut refused: %s" % (mid, lab, se.strip()))
                continue
            q = [f["quality"] for f in mlhost.read_ply(out).faces]
            inter = sum(fa[i] for i in range(len(faces)) if q[i] == 1 and label[i] == lab)
            union = sum(fa[i] for i in range(len(faces)) if q[i] == 1 or label[i] == lab)
            iou = inter / union if union > 0 else 0.0
            ious.append(iou)
            print("mesh %s part %d: %d faces (%.1f%% of the area), boundary cut %d faces off, snake cut IoU %.3f"
                  % (mid, lab, sum(l == lab for l in label), 100 * part / total, bad, iou))
    ious.sort()
    med = ious[len(ious) // 2] if ious else float("nan")
    print("parts: %d, boundary cuts not exact: %d; snake cuts: %d (the others refused), IoU median %.3f, min %.3f, "
          "max %.3f" % (tested, exact_bad, len(ious), med, ious[0] if ious else float("nan"), ious[-1] if ious else float("nan")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
