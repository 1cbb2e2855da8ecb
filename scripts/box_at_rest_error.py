"""Where the pressure error of water at rest in a 3-D box lies (docs/validation/cad_at_rest/
integrals_findings.md, "3-D at rest"): (p - rho0 g (H - z)) / (rho0 g H) of the last snapshot,
RMS and mean by the number of walls (the four sides and the floor) within 1 and 2 dx of a
particle, over all particles and over those at least 2h = 4 dx below the surface, and by row
above the floor (side row: within 1 dx of a side wall).

    /usr/bin/python3 scripts/box_at_rest_error.py RUN_DIR N

for the study's box: 0.08 x 0.08 m, depth H = 0.08 m, dx = H/N, rho0 = 1000, g = 9.81.
"""
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp import read_vtp  # noqa: E402

run, n = sys.argv[1], int(sys.argv[2])
L = H = 0.08; dx = H / n; rho0 = 1000; g = 9.81
f = sorted(glob.glob(run + "/particles_*.vtp"))[-1]
d = read_vtp(f)
x = d["points"]; p = d["pressure"]
e = (p - rho0 * g * (H - x[:, 2])) / (rho0 * g * H)
dist = np.stack([x[:, 0], L - x[:, 0], x[:, 1], L - x[:, 1], x[:, 2]], axis=1)
deep = x[:, 2] < H - 4 * dx
print(f"{f}: N {len(e)}, RMS all {np.sqrt(np.mean(e**2)):.4f}, deep {np.sqrt(np.mean(e[deep]**2)):.4f} ({deep.sum()}), mean all {e.mean():+.4f}")
for lim in (1.0, 2.0):
    k = (dist < lim * dx).sum(axis=1)
    print(f" walls within {lim} dx:", "  ".join(
        f"{c}: rms {np.sqrt(np.mean(e[k == c]**2)):.4f} mean {e[k == c].mean():+.4f} (n {np.sum(k == c)})"
        for c in range(4) if np.any(k == c)))
    print(f"   deep only         :", "  ".join(
        f"{c}: rms {np.sqrt(np.mean(e[(k == c) & deep]**2)):.4f} (n {np.sum((k == c) & deep)})"
        for c in range(4) if np.any((k == c) & deep)))
lay = np.floor(x[:, 2] / dx).astype(int)
side = np.min(dist[:, :4], axis=1) < dx
print(" layer: rms (mean) [side-row rms | inner rms]")
for l in range(n):
    m = lay == l
    if m.any():
        a, b = m & side, m & ~side
        print(f"  {l:2d}: {np.sqrt(np.mean(e[m]**2)):.4f} ({e[m].mean():+.4f})  [{np.sqrt(np.mean(e[a]**2)) if a.any() else float('nan'):.4f} | {np.sqrt(np.mean(e[b]**2)) if b.any() else float('nan'):.4f}]")
