#!/usr/bin/env python3
"""Tables and a plot from gs_parts' CSV (issue 33): closed snakes on part boundaries drawn by people.

    parts_report.py parts.csv OUT_DIR [people.csv]   -> OUT_DIR/parts.md, OUT_DIR/parts_distance.svg

people.csv (gs_parts --people): per part, how many people's own cuts pass the success criterion
against the other people's; with it the category table gets a column for that agreement.

Standard library only, like report.py."""
import csv
import statistics
import sys
from collections import defaultdict


def main(path, out, people_path=None):
    rows = list(csv.DictReader(open(path)))
    people = defaultdict(lambda: [0, 0, []])  # category -> [passing, cuts, per-part shares]
    if people_path:
        for r in csv.DictReader(open(people_path)):
            for c in (r["category"], "ALL"):
                people[c][0] += int(r["passing"])
                people[c][1] += int(r["people"])
                people[c][2].append(int(r["passing"]) / max(int(r["people"]), 1))
    energies = sorted({r["energy"] for r in rows}, key=lambda e: (e != "normal", e))
    cats = sorted({r["category"] for r in rows})
    by = defaultdict(list)
    for r in rows:
        by[(r["energy"], r["category"])].append(r)
        by[(r["energy"], "ALL")].append(r)

    def cell(rs):
        n = len(rs)
        ok = sum(int(r["success"]) for r in rs)
        pts = sum(1 for r in rs if int(r["stopped"]) or float(r["len_ratio"]) < 0.25)
        med = statistics.median(float(r["mean_dist_h"]) for r in rs) if rs else 0
        return "%d/%d (%.0f %%), %d collapsed, median %.2f h" % (ok, n, 100.0 * ok / max(n, 1), pts, med)

    extra = ["people against people"] if people else []
    lines = ["| category | " + " | ".join(energies + extra) + " |", "|---" * (1 + len(energies) + len(extra)) + "|"]
    for c in cats + ["ALL"]:
        cells = [cell(by[(e, c)]) for e in energies]
        if people:
            ok, n, share = people[c]
            cells.append("%d/%d (%.0f %%), %.0f %% per part" % (ok, n, 100.0 * ok / max(n, 1),
                                                               100.0 * statistics.mean(share or [0])))
        lines.append("| %s | " % c + " | ".join(cells) + " |")
    sides = ["| seeds | " + " | ".join(energies) + " |", "|---" * (1 + len(energies)) + "|"]
    for side in ("inside", "outside"):
        for ring in sorted({r["ring"] for r in rows}):
            sides.append("| %s, %s rings off | " % (side, ring) + " | ".join(
                cell([r for r in by[(e, "ALL")] if r["side"] == side and r["ring"] == ring]) for e in energies) + " |")
    md = ["Success: 90 % of the loop within 1 h of a person's cut and 90 % of that cut within 1 h of the loop; "
          "collapsed: stopped by the collapse watch or shorter than a quarter of its start; median: of the mean "
          "distance of the loop to the nearest agreeing person's cut, in mean edge lengths h." + (
              " People against people: each person's own cut, scored like a loop against the other "
              "people's cuts of the part (how often people meet the criterion among themselves); per part: the "
              "mean over parts of the share of their people that pass, weighted as the loops are (4 per part)."
              if people else ""), ""] + lines + [""] + sides
    open(out + "/parts.md", "w").write("\n".join(md) + "\n")
    print("\n".join(md))

    # cumulative share of loops whose mean distance to the cuts is below x (h), per energy
    W, H, L, B = 520, 300, 50, 40
    xmax = 10.0
    colours = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd"]
    svg = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">' % (W, H),
           '<rect width="100%" height="100%" fill="white"/>']
    px = lambda x: L + (W - L - 20) * min(x, xmax) / xmax
    py = lambda y: H - B - (H - B - 20) * y
    svg.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (L, py(0), W - 20, py(0)))
    svg.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (L, py(0), L, py(1)))
    for t in range(0, 11, 2):
        svg.append('<text x="%.1f" y="%d" text-anchor="middle">%d</text>' % (px(t), H - B + 15, t))
    for t in (0, 0.25, 0.5, 0.75, 1):
        svg.append('<text x="%d" y="%.1f" text-anchor="end">%d%%</text>' % (L - 4, py(t) + 4, int(100 * t)))
        svg.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (L, py(t), W - 20, py(t)))
    svg.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#888" stroke-dasharray="4"/>' % (px(1), py(0), px(1), py(1)))
    svg.append('<text x="%d" y="%d" text-anchor="middle">mean distance of the loop to the nearest human cut (edge lengths)</text>' % ((W + L) / 2, H - 8))
    for i, e in enumerate(energies):
        d = sorted(float(r["mean_dist_h"]) for r in by[(e, "ALL")])
        pts = " ".join("%.1f,%.1f" % (px(x), py((k + 1) / len(d))) for k, x in enumerate(d))
        svg.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>' % (colours[i % 4], pts))
        svg.append('<text x="%d" y="%d" fill="%s">%s (%d loops)</text>' % (W - 200, 40 + 15 * i, colours[i % 4], e, len(d)))
    svg.append("</svg>")
    open(out + "/parts_distance.svg", "w").write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else None)
