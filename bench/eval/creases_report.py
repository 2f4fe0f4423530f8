#!/usr/bin/env python3
"""Markdown tables of bench/eval/gs_creases' CSV (issue 38): captured per set and energy, per
mesh, and the misses of the crease energy, beside the crease energy of earlier runs (one column
each, named for the file: creases_before_ends.csv -> "before ends").
usage: creases_report.py creases.csv [before.csv ...]"""
import os
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
    if not n:
        return "-"
    pct = 100.0 * ok / n
    # never "100 %" for a set with a miss (225/226 is 99.6 %)
    return f"{pct:.1f} % ({ok}/{n})" if ok < n and round(pct) == 100 else f"{pct:.0f} % ({ok}/{n})"


def label(path):
    stem = os.path.splitext(os.path.basename(path))[0]
    return "crease energy " + stem.replace("creases_", "").replace("_", " ")


def main():
    rows = load(sys.argv[1])
    befores = [(label(p), load(p)) for p in sys.argv[2:]]
    sets = ["dense", "tess", "shared"]
    head = "".join(f" {name} |" for name, _ in befores)
    rule = "---|" * len(befores)
    print("| set | normal variation | crease energy |" + head)
    print("|---|---|---|" + rule)
    for s in sets + ["all"]:
        key = (lambda r: ("all", r["energy"])) if s == "all" else (lambda r: (r["set"], r["energy"]))
        t = tally(rows, key)
        line = f"| {s} | {cell(t, (s, 'normal'))} | {cell(t, (s, 'crease'))} |"
        for _, b in befores:
            line += f" {cell(tally(b, key), (s, 'crease'))} |"
        print(line)
    print()
    mkey = lambda r: (r["set"] + " " + r["mesh"], r["energy"])
    by_mesh = tally(rows, mkey)
    tbm = [tally(b, mkey) for _, b in befores]
    print("| mesh | normal variation | crease energy |" + head)
    print("|---|---|---|" + rule)
    for m in dict.fromkeys(r["set"] + " " + r["mesh"] for r in rows):
        line = f"| {m} | {cell(by_mesh, (m, 'normal'))} | {cell(by_mesh, (m, 'crease'))} |"
        for t in tbm:
            line += f" {cell(t, (m, 'crease'))} |"
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
