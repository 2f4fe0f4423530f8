#!/usr/bin/env python3
"""parts_stages_rings.py A.err B.err [RINGMAP_B [RINGMAP_A]]: two gs_parts runs with GS_PARTS_STAGES=1
compared row by row and stage by stage, the rings of B (or A) renamed by RINGMAP (e.g. 4:2,6:3: a
refined variant seeded as far off in space as the originals at --rings 2,3; session 33). Prints the
successes after each stage, how many rows succeed on both / only one, and the rows whose snake or
final success differs (the 6 stages' successes as a bit string, the snake's capture/coverage, length)."""
import sys, collections
NAMES = ['snake', 'band', 'descent', 'salience', 'bend', 'final']
def load(p, rm={}):
    d = {}
    for line in open(p):
        if not line.startswith('STAGES'): continue
        head, *st = line.strip().split('|')
        _, i, part, side, ring = head.split()
        ring = rm.get(ring, ring)
        r = {}
        for s in st:
            s = s.split()
            if not s: continue
            cap, cov = map(float, s[2].split('/'))
            r[s[0]] = (int(s[3]), float(s[1][2:-1]), cap, cov)
        d[(i, part, side, ring)] = r
    return d
rmA = dict(x.split(':') for x in sys.argv[4].split(',')) if len(sys.argv) > 4 and sys.argv[4] else {}
rmB = dict(x.split(':') for x in sys.argv[3].split(',')) if len(sys.argv) > 3 and sys.argv[3] else {}
a, b = load(sys.argv[1], rmA), load(sys.argv[2], rmB)
ks = [k for k in a if k in b]
print('rows', len(ks))
for nm, d in (('A', a), ('B', b)):
    print(nm, ' '.join(f'{s}={sum(d[k][s][0] for k in ks)}' for s in NAMES))
for s in NAMES:
    onlyA = [k for k in ks if a[k][s][0] and not b[k][s][0]]
    onlyB = [k for k in ks if b[k][s][0] and not a[k][s][0]]
    print(f'{s}: both {sum(a[k][s][0] and b[k][s][0] for k in ks)} onlyA {len(onlyA)} onlyB {len(onlyB)}')
if True:
    for k in sorted(ks, key=lambda k: (int(k[0]), int(k[1]), k[2], k[3])):
        if a[k]['final'][0] != b[k]['final'][0] or a[k]['snake'][0] != b[k]['snake'][0]:
            fa = ''.join(str(a[k][s][0]) for s in NAMES); fb = ''.join(str(b[k][s][0]) for s in NAMES)
            print(' '.join(k), 'A', fa, 'snake %.2f/%.2f L%.1f' % (a[k]['snake'][2], a[k]['snake'][3], a[k]['snake'][1]),
                  '| B', fb, 'snake %.2f/%.2f L%.1f' % (b[k]['snake'][2], b[k]['snake'][3], b[k]['snake'][1]))
