#!/usr/bin/python3
"""Issue 31 item 4 traces of the 3-D dam break: P1-P5 and H1-H4 of runs beside the MARIN
experiment, from RUN/probes.csv (also of a run still going), t from 0.3 s to the longest record.
usage: dam_break_item4_plot.py OUTPREFIX LABEL=RUN_DIR[:Q] ...   (:Q reads probes Q1.. instead
of P1..). Findings: docs/validation/dam_break_3d/findings.md."""
import sys, csv, math
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import os
EXP = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'data', 'spheric2',
                   'test_case_2_exp_data.dat')
rows = [l.split() for l in open(EXP).read().splitlines() if l.strip()]
rows = [r for r in rows if r[0][0].isdigit()]
te = [float(r[0]) for r in rows]
col = {f'P{k}': k for k in range(1, 9)}
col.update({'H3': 9, 'H2': 10, 'H1': 11, 'H4': 12})
out = sys.argv[1]
runs = []
for a in sys.argv[2:]:
    lab, d = a.split('=', 1)
    pre = 'P'
    if d.endswith(':Q'): d, pre = d[:-2], 'Q'
    sim = [r for r in csv.DictReader(open(d + '/probes.csv')) if r.get('H4.height') not in (None, '')]
    runs.append((lab, pre, sim))
tend = max(float(s[-1]['time']) for _, _, s in runs)
tend = min(1.5, tend)
T0 = 0.3
def fig(names, fname, kind):
    f, axes = plt.subplots(len(names), 1, figsize=(9, 2.0 * len(names)), sharex=True)
    for ax, n in zip(axes, names):
        k = col[n]
        ax.plot([t for t in te if t <= tend], [float(r[k]) / (1000 if kind == 'p' else 1) for t, r in zip(te, rows) if t <= tend], 'k-', lw=0.9, label='experiment')
        for lab, pre, sim in runs:
            key = (pre + n[1:] + '.p_wall') if kind == 'p' else (n + '.height')
            v = []
            for r in sim:
                x = float(r[key]) if r[key] not in ('', 'nan') else float('nan')
                v.append((0.0 if math.isnan(x) else x) / (1000 if kind == 'p' else 1))
            ax.plot([float(r['time']) for r in sim], v, lw=0.8, label=lab)
        ax.set_ylabel(n + (' (kPa)' if kind == 'p' else ' (m)'))
        ax.grid(alpha=0.3); ax.set_xlim(T0, tend)
        if kind == 'p': ax.set_ylim(-60, 70)
    axes[-1].set_xlabel('t (s)')
    axes[0].legend(fontsize=7, ncol=2)
    f.tight_layout(); f.savefig(fname, dpi=90); plt.close(f)
fig(['P1', 'P2', 'P3', 'P4', 'P5'], out + 'pressures.png', 'p')
fig(['H1', 'H2', 'H3', 'H4'], out + 'heights.png', 'h')
