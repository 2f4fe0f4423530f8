#!/usr/bin/env python3
"""Markdown tables of bench/eval/gs_creases' CSV (issue 38): captured per set and energy, per
mesh, and the misses of the crease energy.  usage: creases_report.py creases.csv [before.csv]"""
import csv
import sys
from collections import defaultdict


def load(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def tally(rows, key):
    t = defaultdict(lambda: [0, 0])
    for r in rows:
        k = key(r)
        t[k][0] += 1
        t[k][1] += r["captured"] == "1"
    return t


def cell(t, k):
    n, ok = t.get(k, (0, 0))
    return f"{100.0 * ok / n:.0f} % ({ok}/{n})" if n else "-"


def main():
    rows = load(sys.argv[1])
    before = load(sys.argv[2]) if len(sys.argv) > 2 else None
    sets = ["dense", "tess", "shared"]
    by_set = tally(rows, lambda r: (r["set"], r["energy"]))
    print("| set | normal variation | crease energy |" + (" crease energy before |" if before else ""))
    print("|---|---|---|" + ("---|" if before else ""))
    tb = tally(before, lambda r: (r["set"], r["energy"])) if before else None
    for s in sets + ["all"]:
        key = (lambda r: ("all", r["energy"])) if s == "all" else None
        t = tally(rows, key) if key else by_set
        line = f"| {s} | {cell(t, (s, 'normal'))} | {cell(t, (s, 'crease'))} |"
        if before:
            b = tally(before, key) if key else tb
            line += f" {cell(b, (s, 'crease'))} |"
        print(line)
    print()
    by_mesh = tally(rows, lambda r: (r["set"] + " " + r["mesh"], r["energy"]))
    tbm = tally(before, lambda r: (r["set"] + " " + r["mesh"], r["energy"])) if before else None
    print("| mesh | normal variation | crease energy |" + (" crease energy before |" if before else ""))
    print("|---|---|---|" + ("---|" if before else ""))
    for m in dict.fromkeys(r["set"] + " " + r["mesh"] for r in rows):
        line = f"| {m} | {cell(by_mesh, (m, 'normal'))} | {cell(by_mesh, (m, 'crease'))} |"
        if before:
            line += f" {cell(tbm, (m, 'crease'))} |"
        print(line)
    print()
    print("Misses of the crease energy (capture / coverage / mean distance in h):")
    print()
    for r in rows:
        if r["energy"] == "crease" and r["captured"] != "1":
            kind = "closed" if r["closed"] == "1" else "open"
            print(f"- {r['set']} {r['mesh']} chain {r['chain']} {kind} {r['offset']} h: "
                  f"{100 * float(r['capture']):.0f} % / {100 * float(r['coverage']):.0f} % / {float(r['mean_dist_h']):.2f} h")


if __name__ == "__main__":
    main()
