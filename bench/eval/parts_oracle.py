#!/usr/bin/env python3
"""The Run's end's choice against every loop it found (issue 33, docs/method.md session 28).

    GS_PARTS_ORACLE=oracle.csv gs_parts --energy part --rings 2,3 --out parts.csv
    python3 bench/eval/parts_oracle.py oracle.csv

Prints the ceiling of any choice among the recorded edge loops (per category, and the stages
that found the successful loops on the failed rows), the successes that have a failing loop
as cheap per length or as salient nearby, and replays selection rules on the recorded loops
(the choice only: the loops are those the pipeline generates now).
"""
import collections
import csv
import sys

NUM = ['capture', 'coverage', 'L_h', 'cpl', 'e_pl', 'c_pl', 'area_share', 'sal', 'sal_w', 'd_own_h', 'own_agree',
       'plane_h', 'turn', 'e_loop', 'e_part', 'e_body']
# session 29's support columns (files recorded since): times found, mutual captures (count, weighted by
# times found, soft: the sum of min(share either way)), and with the snake's and the seeded loop
SUPPORT = ['mult', 'sup', 'sup_m', 'sup_soft', 'sup_own', 'sup_seed']
# the bend across (LoopBend, crossDist units) and whether Across started from the loop (session 29, helper 3b)
BEND = ['bend', 'xfrom']


def load(path):
    rows = collections.OrderedDict()
    for r in csv.DictReader(open(path)):
        if r['energy'] != 'part':
            continue
        for f in NUM + SUPPORT + BEND:
            r[f] = float(r[f]) if r.get(f, '') != '' else float('nan')
        r['success'], r['chosen'] = r['success'] == '1', r['chosen'] == '1'
        rows.setdefault((r['id'], r['category'], r['part'], r['side'], r['ring']), []).append(r)
    return rows


def name(k):
    return f'{k[1]} {k[0]} part {k[2]} {k[3]} {k[4]}'


def replay(rows, pick, label):
    """pick(edge loops, chosen) -> the loop taken; prints the total and the rows gained and lost."""
    ok, plus, minus = 0, [], []
    for k, v in rows.items():
        ch = next(c for c in v if c['chosen'])
        c = pick(v[1:], ch) if ch['stage'] != 'snake' and len(v) > 1 else ch
        ok += c['success']
        if c['success'] != ch['success']:
            (plus if c['success'] else minus).append(k)
    print(f'{label}: {ok}/{len(rows)} (+{len(plus)} -{len(minus)})' +
          ''.join(f'\n   {"+" if k in plus else "-"} {name(k)}' for k in plus + minus if len(plus + minus) <= 12))


def main():
    rows = load(sys.argv[1])
    cat = collections.defaultdict(lambda: [0, 0, 0, 0])  # rows, ok, + an edge loop, + the snake's loop too
    stages = collections.Counter()
    for k, v in rows.items():
        ch = next(c for c in v if c['chosen'])
        good = [c for c in v[1:] if c['success']]
        for key in (k[1], 'ALL'):
            t = cat[key]
            t[0] += 1
            t[1] += ch['success']
            t[2] += not ch['success'] and bool(good)
            t[3] += not ch['success'] and (bool(good) or v[0]['success'])
        if not ch['success'] and good:
            stages.update({s.split('+')[0] for c in good for s in c['stage'].split('|')})
            b = min(good, key=lambda c: c['cpl'])
            print(f'{name(k)}: chosen {ch["stage"].split("|")[0]} {ch["capture"]:.2f}/{ch["coverage"]:.2f}, '
                  f'successful {b["stage"].split("|")[0]}: cost per length x{b["cpl"] / ch["cpl"]:.3f}, '
                  f'salience x{b["sal"] / ch["sal"]:.3f} (with width x{b["sal_w"] / ch["sal_w"]:.3f}), planarity x{b["plane_h"] / ch["plane_h"]:.2f}')
    print('category   rows  ok  ceiling  with the snake\'s own loop')
    for c, t in sorted(cat.items()):
        print(f'{c:10s} {t[0]:4d} {t[1]:3d} {t[1] + t[2]:6d} {t[1] + t[3]:8d}')
    print('stages with a successful loop on failed rows:', dict(stages))
    for tol in (1.0, 1.05, 1.1):
        n = sum(1 for v in rows.values() for ch in [next(c for c in v if c['chosen'])]
                if ch['success'] and ch['stage'] != 'snake' and any(
                    not c['success'] and (c['cpl'] <= tol * ch['cpl'] or 0 < c['sal_w'] <= tol * ch['sal_w']) for c in v[1:]))
        print(f'successes with a failing loop within {tol}x the chosen one\'s cost per length or salience: {n}')
    replay(rows, lambda e, ch: ch, 'chosen')
    replay(rows, lambda e, ch: min(e, key=lambda c: c['cpl']), 'cheapest per length')
    replay(rows, lambda e, ch: min(e, key=lambda c: c['sal'] if c['sal'] > 0 else 1e9), 'most salient (no width)')
    replay(rows, lambda e, ch: min(e, key=lambda c: c['sal_w'] if c['sal_w'] > 0 else 1e9), 'most salient (width)')
    for t, p in ((1.05, 0.5), (1.3, 0.5), (1.3, 0.6), (1.3, 0.7)):
        def flatter(e, ch, t=t, p=p):
            cs = [c for c in e if c is not ch and c['cpl'] <= t * ch['cpl'] and c['plane_h'] <= p * ch['plane_h']
                  and 0.5 * ch['L_h'] < c['L_h'] < 2 * ch['L_h']]
            return min(cs, key=lambda c: c['cpl']) if cs else ch
        replay(rows, flatter, f'flatter x{p}, at most x{t} per length')
    if any(c['bend'] == c['bend'] for v in rows.values() for c in v[1:]):
        bend_rules(rows)
    if any(c.get('verts') for v in rows.values() for c in v[1:]):
        seeding_rules(rows)
    if not any(c['mult'] == c['mult'] for v in rows.values() for c in v[1:]):
        return
    # support (session 29, after Golovinskiy and Funkhouser's randomized cuts: cut where many cuts agree)
    for lab, f in (('sup', lambda c: c['sup']), ('sup_m', lambda c: c['sup_m']), ('soft', lambda c: c['sup_soft']),
                   ('sup+own+seed', lambda c: c['sup'] + c['sup_own'] + c['sup_seed']), ('times found', lambda c: c['mult'])):
        replay(rows, lambda e, ch, f=f: min(e, key=lambda c: (-f(c), c['cpl'])), f'most support ({lab}), ties by cost per length')
        for t in (1.01, 1.05, 1.1, 1.3):
            def more(e, ch, f=f, t=t):
                cs = [c for c in e if c['cpl'] <= t * ch['cpl'] and f(c) > f(ch) and 0.5 * ch['L_h'] < c['L_h'] < 2 * ch['L_h']]
                return min(cs, key=lambda c: (-f(c), c['cpl'])) if cs else ch
            replay(rows, more, f'  more support ({lab}) at most x{t} per length')
        for t in (1.002, 1.005, 1.01, 1.02):
            def tie(e, ch, f=f, t=t):
                cs = [c for c in e if c['cpl'] <= t * ch['cpl'] and 0.5 * ch['L_h'] < c['L_h'] < 2 * ch['L_h']] + [ch]
                return max(cs, key=lambda c: (f(c), c is ch, -c['cpl']))
            replay(rows, tie, f'  near ties (x{t} per length) to the most support ({lab})')


def seeding_rules(rows):
    """Session 36: the part's four seedings (inside/outside, rings 2 and 3) as votes: how many of them
    found each loop (`verts` names it) and how many chose it. Cross-row, so a ceiling for a Run's end
    that would search from the other side too, not a rule one Run can apply."""
    reach, chose = collections.Counter(), collections.Counter()
    for k, v in rows.items():
        for c in v[1:]:
            reach[(k[0], k[2], c['verts'])] += 1
            chose[(k[0], k[2], c['verts'])] += c['chosen']
    for k, v in rows.items():
        for c in v[1:]:
            c['reach'], c['chose'] = reach[(k[0], k[2], c['verts'])], chose[(k[0], k[2], c['verts'])]
    for f in ('chose', 'reach'):
        for t in (1.0, 1.02, 1.05, 1.1, 1.3):
            def most(e, ch, f=f, t=t):
                cs = [c for c in e if c['cpl'] <= t * ch['cpl'] and 0.5 * ch['L_h'] < c['L_h'] < 2 * ch['L_h']] + [ch]
                return max(cs, key=lambda c: (c[f], c is ch, -c['cpl']))
            replay(rows, most, f'the loop most seedings {"chose" if f == "chose" else "found"}, at most x{t} per length')


def bend_rules(rows):
    """Session 29: the bend across's own candidates (stage `across`) against the chosen loop."""
    def across(e, ch):
        return [c for c in e if c is not ch and 'across' in c['stage'] and c['bend'] == c['bend']
                and 0.5 * ch['L_h'] < c['L_h'] < 2 * ch['L_h']]
    print('failed rows where a loop of the bend across succeeds (bend, cost per length, off the plane against the chosen):')
    for k, v in rows.items():
        ch = next(c for c in v if c['chosen'])
        good = [c for c in v[1:] if 'across' in c['stage'] and c['success']]
        if ch['success'] or not good:
            continue
        print(f'  {name(k)}: chosen bend {ch["bend"]:.3f}; ' + ', '.join(
            f'{c["bend"]:.3f} x{c["cpl"] / ch["cpl"]:.3f} plane x{c["plane_h"] / ch["plane_h"]:.2f}' for c in good))
    for q in (1.0, 1.2, 1.5):
        for t in (1.0, 1.05, 1.1):
            def more(e, ch, q=q, t=t):
                cs = [c for c in across(e, ch) if ch['bend'] == ch['bend'] and c['bend'] > max(q * ch['bend'], ch['bend'])
                      and c['cpl'] <= t * ch['cpl']]
                return max(cs, key=lambda c: c['bend']) if cs else ch
            replay(rows, more, f'bends more than x{q} the chosen (no gain in h), at most x{t} per length' +
                   (' (dominance: crossDominant)' if q == 1.0 and t == 1.0 else ''))
    for k in (0.25, 0.5, 1.0):
        def grow(e, ch, k=k):
            cs = [c for c in across(e, ch) if ch['bend'] == ch['bend'] and c['bend'] > max(1.2 * ch['bend'], ch['bend'] + 0.1)
                  and c['cpl'] <= ch['cpl'] * (1.05 + k * (c['bend'] - ch['bend']))]
            return max(cs, key=lambda c: c['bend']) if cs else ch
        replay(rows, grow, f'price 1.05 + {k} x the bend gained (h)')
    for p in (0.4, 0.5, 0.6, 0.7):
        for t in (1.05, 1.1, 1.3):
            def flat(e, ch, p=p, t=t):
                cs = [c for c in across(e, ch) if c['plane_h'] <= p * ch['plane_h'] and c['cpl'] <= t * ch['cpl'] and c['bend'] > 0]
                return min(cs, key=lambda c: c['cpl']) if cs else ch
            replay(rows, flat, f'flatter x{p} and concave across, at most x{t} per length')


if __name__ == '__main__':
    main()
