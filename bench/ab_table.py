#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Before/after tables of bench/ab_benchmarks.sh (secant solves and whole solves).

Usage: ab_table.py OUT_DIR (the directory bench/ab_benchmarks.sh wrote)."""
import json, statistics, sys, glob
d = sys.argv[1]
def med(path):
    out = {}
    for b in json.load(open(path))['benchmarks']:
        if b.get('aggregate_name') == 'median':
            out[b['run_name']] = b
    return out
sb, sa = med(f'{d}/secant_before.json'), med(f'{d}/secant_after.json')
print('| secant_solve | dofs | iterations (before/after) | per it before [ms] | per it after [ms] | assembly/it before | after | after/before (per it) |')
print('|---|---|---|---|---|---|---|---|')
for name in sb:
    if not name.startswith('secant_solve') or name not in sa: continue
    b, a = sb[name], sa[name]
    print(f"| {name.split('/')[1]} | {int(b['dofs'])} | {int(b['iterations'])}/{int(a['iterations'])} | {b['per_iteration_s']*1e3:.2f} | {a['per_iteration_s']*1e3:.2f} | {b['assembly_per_it_s']*1e3:.2f} | {a['assembly_per_it_s']*1e3:.2f} | {a['per_iteration_s']/b['per_iteration_s']:.3f} |")
for name in sb:
    if name.startswith('bare') and name in sa:
        print('bare', name, f"{sb[name]['real_time']:.2f} {sa[name]['real_time']:.2f}")
def runs(side):
    r = {}
    for p in sorted(glob.glob(f'{d}/method_{side}_*.json')):
        for b in json.load(open(p))['benchmarks']:
            r.setdefault(b['name'], []).append(b)
    return r
mb, ma = runs('before'), runs('after')
if mb:
    print()
    print('| method_solve (k/10μ/method) | dofs | its b/a | solver before [s] | solver after [s] | total before [s] | total after [s] | solver after/before |')
    print('|---|---|---|---|---|---|---|---|')
    for name in mb:
        if name not in ma: continue
        b = statistics.median(x['solver_s'] for x in mb[name]); a = statistics.median(x['solver_s'] for x in ma[name])
        tb = statistics.median(x['total_s'] for x in mb[name]); ta = statistics.median(x['total_s'] for x in ma[name])
        ib = int(mb[name][0]['iterations']); ia = int(ma[name][0]['iterations'])
        print(f"| {name.replace('method_solve/','').replace('/iterations:1','')} | {int(mb[name][0]['dofs'])} | {ib}/{ia} | {b:.3f} | {a:.3f} | {tb:.2f} | {ta:.2f} | {a/b:.3f} |")
