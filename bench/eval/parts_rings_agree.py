#!/usr/bin/env python3
"""parts_rings_agree.py ORIGINAL.csv VARIANT.csv: rows succeeding on the original (success) and on a
variant seeded as far off in space (success_h0, its rings 4, 6 read as 2, 3; session 33): both, only one."""
import csv,sys
def load(p,rm,col):
    d={}
    for r in csv.DictReader(open(p)):
        if r['energy']!='part': continue
        d[(r['id'],r['part'],r['side'],rm.get(r['ring'],r['ring']))]=r.get(col, r['success'])=='1'
    return d
o=load(sys.argv[1],{},'success'); v=load(sys.argv[2],{'4':'2','6':'3'},'success_h0')
ks=[k for k in o if k in v]
print(sys.argv[2], 'orig',sum(o[k] for k in ks),'var',sum(v[k] for k in ks),'both',sum(o[k] and v[k] for k in ks),'only orig',sum(o[k] and not v[k] for k in ks),'only var',sum(v[k] and not o[k] for k in ks))
