#!/usr/bin/env python3
"""Issue 31 item 4's figures of the 3-D dam break from a run's probes.csv, also of a run still
going (the analysis writes metrics.json only at the end): the rules of
src/curvsph/analysis/dam_break_analysis.hpp (impact = first P1 above 20 % of the experimental
P1 peak, first peak = P1's maximum within the experiment's impact-to-peak time after it, RMS
over t <= min(1.5 s, TMAX, end) over the experimental P1 peak or 0.55 m, a dry sensor reads 0).
usage: dam_break_item4.py RUN_DIR [P|Q (probe name prefix)] [TMAX] [json]
Findings: docs/validation/dam_break_3d/findings.md (issue 31 item 4)."""
import sys, csv, math, bisect, json, os
EXP = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'data', 'spheric2',
                   'test_case_2_exp_data.dat')
rows = [l.split() for l in open(EXP).read().splitlines() if l.strip()]
rows = [r for r in rows if r[0][0].isdigit() or r[0][0] == '-']
te = [float(r[0]) for r in rows]
col = {f'P{k}': k for k in range(1, 9)}
col.update({'H3': 9, 'H2': 10, 'H1': 11, 'H4': 12})
def ei(name, t):
    k = col[name]; i = bisect.bisect_left(te, t)
    if i <= 0: return float(rows[0][k])
    if i >= len(te): return float(rows[-1][k])
    a = (t - te[i-1]) / (te[i] - te[i-1])
    return (1-a)*float(rows[i-1][k]) + a*float(rows[i][k])
d = sys.argv[1]; pre = sys.argv[2] if len(sys.argv) > 2 else 'P'
tmax = float(sys.argv[3]) if len(sys.argv) > 3 else 1.5
sim = list(csv.DictReader(open(d + '/probes.csv')))
sim = [r for r in sim if r.get('H4.height') not in (None, '')]
t = [float(r['time']) for r in sim]
end = min(tmax, t[-1]); idx = [i for i in range(len(t)) if t[i] <= end + 1e-12]
def s(name, i):
    key = (pre + name[1:] if name[0] == 'P' else name) + ('.height' if name[0] == 'H' else '.p_wall')
    v = float(sim[i][key]) if sim[i][key] not in ('', 'nan') else float('nan')
    return 0.0 if math.isnan(v) else v
# experiment peak / impact over [0, 1.5]
ex = [(tt, float(r[1])) for tt, r in zip(te, rows) if tt <= 1.5]
p1pe = max(v for _, v in ex); tpe = [tt for tt, v in ex if v == p1pe][0]
thr = 0.2 * p1pe
ti_e = next(tt for tt, v in ex if v > thr)
rise = tpe - ti_e
out = {'end': end}
ti = next((t[i] for i in idx if s('P1', i) > thr), float('nan'))
out['p1_impact_time'] = ti; out['impact_error_s'] = ti - ti_e
fp = [s('P1', i) for i in idx if ti - 1e-12 <= t[i] <= ti + rise + 1e-12]
out['p1_first_peak'] = max(fp) if fp else float('nan'); out['p1_first_peak_ratio'] = out['p1_first_peak'] / p1pe
out['p1_peak'] = max(s('P1', i) for i in idx)
for k in range(1, 5):
    e2 = [(s(f'P{k}', i) - ei(f'P{k}', t[i]))**2 for i in idx]
    out[f'p{k}_rms'] = math.sqrt(sum(e2)/len(e2)) / p1pe
for k in range(1, 5):
    e2 = [(s(f'H{k}', i) - ei(f'H{k}', t[i]))**2 for i in idx]
    out[f'h{k}_rms'] = math.sqrt(sum(e2)/len(e2)) / 0.55
for k in range(1, 9):
    m = min((s(f'P{k}', i), t[i]) for i in idx)
    out[f'p{k}_min'] = m[0]; out[f'p{k}_min_t'] = m[1]
out['sensor_min'] = min(out[f'p{k}_min'] for k in range(1, 9))
out['exp_p1_peak'] = p1pe; out['exp_impact'] = ti_e
if len(sys.argv) > 4: print(json.dumps(out))
else:
    print(f"{d} [{pre}] t<= {end:.3f}: impact {ti:.3f} ({ti-ti_e:+.3f}), first peak {out['p1_first_peak']:.0f} ({out['p1_first_peak_ratio']:.2f}), P1 max {out['p1_peak']:.0f}")
    print('  RMS P1-P4 ' + ', '.join(f"{out[f'p{k}_rms']:.2f}" for k in range(1, 5)) + '; H1-H4 ' + ', '.join(f"{out[f'h{k}_rms']:.3f}" for k in range(1, 5)))
    print('  min ' + ', '.join(f"P{k} {out[f'p{k}_min']/1000:.1f}@{out[f'p{k}_min_t']:.3f}" for k in range(1, 9)))
