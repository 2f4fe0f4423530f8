#!/usr/bin/env python3
"""parts_stages.py CLEAN.err NOISY.err: the rows whose loop succeeds on the 9 meshes and fails on a
variant, by the stage of the Run's end where the variant's loop goes wrong (session 30).

Both files are gs_parts' stderr with GS_PARTS_STAGES=1, e.g.
  GS_PARTS_STAGES=1 gs_parts --energy part --rings 2,3 --out /tmp/c.csv 2> clean.err
  GS_PARTS_STAGES=1 gs_parts --energy part --rings 2,3 --variant noise --out /tmp/n.csv 2> noisy.err
A row counts at the stage where the variant's loop stops succeeding ("lost at"), or, when it never
succeeds, at the stage where the clean loop first does ("never ok"). Also prints the successes
after each stage."""
import collections, sys

NAMES = ['snake', 'band', 'descent', 'salience', 'bend', 'final']


def load(p):
    d = {}
    for line in open(p):
        if not line.startswith('STAGES'):
            continue
        head, *st = line.strip().split('|')
        _, i, part, side, ring = head.split()
        r = {}
        for s in st:
            s = s.split()
            if not s:
                continue
            cap, cov = map(float, s[2].split('/'))
            r[s[0]] = (int(s[3]), float(s[1][2:-1]), cap, cov)  # success, length in h, capture, coverage
        d[(i, part, side, ring)] = r
    return d


def main():
    clean, noisy = load(sys.argv[1]), load(sys.argv[2])
    cnt, rows = collections.Counter(), collections.defaultdict(list)
    for k in clean:
        if k not in noisy:
            continue
        c, n = clean[k], noisy[k]
        if not (c['final'][0] == 1 and n['final'][0] == 0):
            continue
        ok = [n[s][0] for s in NAMES]
        if any(ok):
            tag = 'lost at ' + NAMES[max(i for i in range(6) if ok[i]) + 1]
        else:
            tag = 'never ok (clean ok from ' + NAMES[min(i for i in range(6) if c[NAMES[i]][0])] + ')'
        cnt[tag] += 1
        rows[tag].append(k)
    print('rows ok clean, failed on the variant:', sum(cnt.values()))
    for t, v in cnt.most_common():
        print(f'{v:3d}  {t}  ' + ' '.join(f'{m}:{x}' for m, x in sorted(collections.Counter(k[0] for k in rows[t]).items())))
    for nm, d in (('clean', clean), ('variant', noisy)):
        print(nm, ' '.join(f'{s}={sum(d[k][s][0] for k in d)}' for s in NAMES))


if __name__ == '__main__':
    main()
