#!/usr/bin/env python3
"""parts_side.py GS_PARTS_SIDE.err [MINCOV]: session 34's summary of `GS_PARTS_SIDE=1 gs_parts ...
--energy part` stderr. On which side of the loop the agreeing people's cuts lie (signed hop, + on the
part's side; each distinct loop and person once, coverage >= MINCOV, default 0.5; loops whose vertex
chain does not separate the mesh left out), the mean profile across the loops, how often a measure
picks the people's majority side, and the rows a one-ring shift of the loop would pass."""
import collections, math, sys

err = sys.argv[1]
mincov = float(sys.argv[2]) if len(sys.argv) > 2 else 0.5
prof, bad, rowprof, shift = {}, set(), {}, {}
pairs = []  # (group, loop key, counts by signed hop, cut angle, loop angle)
seen = set()


def parse_prof(line):
    d = {}
    for x in line.split('|')[1].split():
        h, v = x.split(':')
        f = dict(y.split('=') for y in v.split(','))
        d[int(h)] = (float(f['H']), float(f['E']), float(f.get('A', 'nan')))
    return d


for line in open(err):
    t = line.split()
    if line.startswith('SIDEPROFILE'):
        k = (t[1], t[2], t[6])
        if 'comps=2 ' not in line: bad.add(k)
        d = parse_prof(line)
        prof[k] = (d, t[5] == 'ok=1', float(t[10].split('=')[1]))
        rowprof[tuple(t[1:5])] = d
    elif line.startswith('SIDESHIFT'):
        shift[tuple(t[1:5])] = (t[5] == 'ok=1', line.split('okPart=')[1][0] == '1', line.split('okBody=')[1][0] == '1')
    elif line.startswith('SIDE '):
        head, rest = line.split('|')[:2]
        t = head.split()
        k = (t[1], t[2], t[6], t[7])
        if float(t[9].split('=')[1]) < mincov or k[:3] in bad or k in seen: continue
        seen.add(k)
        c = {int(x.split(':')[0]): int(x.split(':')[1].split(',')[0]) for x in rest.split()}
        pairs.append(('pass' if t[5] == 'ok=1' else 'fail', k[:3], c, float(t[11].split('=')[1])))

for g in ('pass', 'fail'):
    tot = collections.Counter()
    lean = collections.Counter()
    for gg, k, c, a in pairs:
        if gg != g: continue
        tot.update(c)
        ps, bs = c[1] + c[2] + c[3], c[-1] + c[-2] + c[-3]
        lean['part' if ps > bs else 'body' if bs > ps else ('on' if ps == 0 else 'tie')] += 1
    n = sum(tot.values())
    print(g, 'cut vertices by signed hop:', ' '.join('%+d:%.0f%%' % (h, 100 * tot[h] / max(1, n)) for h in range(-3, 4)),
          '| pairs leaning:', dict(lean))
# one person keeps to a side; the people of a loop agree how much
maj, byloop = [], collections.defaultdict(list)
for g, k, c, a in pairs:
    ps, bs = c[1] + c[2] + c[3], c[-1] + c[-2] + c[-3]
    if ps + bs == 0: continue
    maj.append(max(ps, bs) / (ps + bs))
    if ps != bs: byloop[k].append(1 if ps > bs else 0)
q = sum(sum(v) for v in byloop.values()) / max(1, sum(len(v) for v in byloop.values()))
big = [v for v in byloop.values() if len(v) >= 4]
emax = lambda m: sum(math.comb(m, j) * q ** j * (1 - q) ** (m - j) * max(j, m - j) / m for j in range(m + 1))
print('pairs off the loop %d: share on their majority side %.2f, wholly one side %d' % (len(maj), sum(maj) / len(maj), sum(x == 1 for x in maj)))
print('loops with 4+ people off them %d: mean majority share %.2f (independent people at p(part) %.2f: %.2f), all one side %d' %
      (len(big), sum(max(sum(v), len(v) - sum(v)) / len(v) for v in big) / len(big), q, sum(emax(len(v)) for v in big) / len(big),
       sum(sum(v) in (0, len(v)) for v in big)))
# the mean profile across the loops
for g in ('pass', 'fail'):
    ks = [k for k, (d, ok, a) in prof.items() if k not in bad and ok == (g == 'pass')]
    for i, nm in ((2, 'A along'), (1, 'E'), (0, 'H')):
        print(g, 'loops %d %-8s' % (len(ks), nm), ' '.join('%+d:%.2f' % (h, sum(prof[k][0][h][i] for k in ks) / len(ks)) for h in range(-3, 4)))
# measures that could pick the side
rules = {'lower E ring 1': lambda d: d[1][1] < d[-1][1], 'more concave along ring 1': lambda d: d[1][2] < d[-1][2],
         'more concave H ring 1': lambda d: d[1][0] < d[-1][0], 'ring 1 nearer H=0': lambda d: abs(d[1][0]) < abs(d[-1][0]),
         'always the part': lambda d: True}
side = collections.defaultdict(lambda: [0, 0])
for g, k, c, a in pairs:
    side[k][0] += c[1] + c[2]
    side[k][1] += c[-1] + c[-2]
for nm, r in rules.items():
    out = []
    for g in ('pass', 'fail'):
        right = wrong = 0
        for k, (ps, bs) in side.items():
            if ps == bs or ps + bs < 4 or prof[k][1] != (g == 'pass'): continue
            if r(prof[k][0]) == (ps > bs): right += 1
            else: wrong += 1
        out.append('%s %d/%d' % (g, right, right + wrong))
    ok = gain = loss = 0
    for k, (o, a, b) in shift.items():
        s = a if r(rowprof[k]) else b
        ok, gain, loss = ok + s, gain + (s and not o), loss + (o and not s)
    print('%-26s picks the people\'s side: %s; the loop shifted that way: %d/%d +%d -%d' % (nm, ', '.join(out), ok, len(shift), gain, loss))
o = sum(x[0] for x in shift.values())
print('rows %d: as they are %d, toward the part %d, toward the body %d, best of three %d' %
      (len(shift), o, sum(x[1] for x in shift.values()), sum(x[2] for x in shift.values()), sum(any(x) for x in shift.values())))
