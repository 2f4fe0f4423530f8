#!/usr/bin/env python3
"""The Run-end rules on tessellation variants (issue 33, docs/method.md session 29).

    for v in none refine graded noise; do for r in "all:" "nobend:--cross-bend 0" "nosal:--salience 0" \\
        "noprof:--profile-slope 0" "nowidth:--salience-width 0" "noseeded:--seeded-shrink 0" \\
        "notoward:--no-toward-body" "novalley:--no-valley-loop"; do
      nice gs_parts --energy part --rings 2,3 --variant $v ${r#*:} --out DIR/${v}_${r%%:*}.csv; done; done
    python3 bench/eval/parts_variants.py DIR

(--variant none is the benchmark as it is.) Prints successes per variant with every rule on and
with each rule off, and each rule's worth (all on minus rule off: +rows it gains, -rows it
loses). On a variant the success read is `success_h0`: the benchmark's criterion with the
tolerance in the original mesh's h (on a refined mesh 1 new h is half the distance in space,
and people's cuts no longer pass against each other: gs_parts --people); `--h` reads `success`
(the new mesh's h) instead. A missing file is shown as '-'.
"""
import csv
import os
import sys

VARIANTS = ['none', 'refine', 'graded', 'noise']
RULES = [('all', 'all on'), ('nobend', '--cross-bend 0'), ('nosal', '--salience 0'),
         ('noprof', '--profile-slope 0'), ('nowidth', '--salience-width 0'), ('noseeded', '--seeded-shrink 0'),
         ('notoward', '--no-toward-body'), ('novalley', '--no-valley-loop')]


def load(path, new_h):
    if not os.path.exists(path):
        return None
    rows = {}
    for r in csv.DictReader(open(path)):
        if r['energy'] != 'part':
            continue
        col = 'success_h0' if 'success_h0' in r and not new_h else 'success'
        rows[(r['id'], r['part'], r['side'], r['ring'])] = r[col] == '1'
    return rows


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    new_h = '--h' in sys.argv
    d = args[0] if args else '.'
    runs = {(v, t): load(os.path.join(d, '%s_%s.csv' % (v, t)), new_h) for v in VARIANTS for t, _ in RULES}
    print('%-20s' % 'rule off', ''.join('%-24s' % v for v in VARIANTS))
    for t, flag in RULES:
        cells = []
        for v in VARIANTS:
            a, b = runs[(v, 'all')], runs[(v, t)]
            if b is None:
                cells.append('-')
            elif t == 'all' or a is None:
                cells.append('%d/%d' % (sum(b.values()), len(b)))
            else:
                gain = sum(a[k] and not b.get(k, False) for k in a)
                loss = sum(b.get(k, False) and not a[k] for k in a)
                cells.append('%d/%d %+d (+%d -%d)' % (sum(b.values()), len(b), sum(a.values()) - sum(b.values()), gain, loss))
        print('%-20s' % flag, ''.join('%-24s' % c for c in cells))


if __name__ == '__main__':
    main()
