"""Circular Couette start-up from rest: SPH snapshots against the exact transient.

Usage: couette_transient.py RUN_DIR OUTPUT_EVERY_S [BINS] [NU]
The reference is the azimuthal momentum equation
  du/dt = nu (u'' + u'/r - u/r^2),  u(R_i) = omega R_i,  u(R_o) = 0,  u(r, 0) = 0
on 301 points (Crank-Nicolson after 20 implicit-Euler steps that damp the start's jump),
independent of the solver. For every snapshot it prints the rms of v_theta against the
transient and against the steady profile A r + B/r (both over omega R_i), the radial velocity
rms, and the bin means of v_theta (SPH/transient) in BINS equal radial bins.
Defaults: cases/couette.yaml (R_i = 0.025, R_o = 0.04, omega = 1, nu = 1e-6).
"""
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp import read_vtp  # noqa: E402

RI, RO, OMEGA = 0.025, 0.040, 1.0


def profiles(nu, n=301):
    r = np.linspace(RI, RO, n)
    dr = r[1] - r[0]
    a = RI**2 * OMEGA / (RI**2 - RO**2)
    b = -a * RO**2
    ri = r[1:-1]
    m = n - 2
    lap = np.zeros((m, m))
    for k in range(m):
        lap[k, k] = -2 / dr**2 - 1 / ri[k] ** 2
        if k > 0:
            lap[k, k - 1] = 1 / dr**2 - 1 / (2 * dr * ri[k])
        if k < m - 1:
            lap[k, k + 1] = 1 / dr**2 + 1 / (2 * dr * ri[k])
    bc = np.zeros(m)
    bc[0] = (1 / dr**2 - 1 / (2 * dr * ri[0])) * OMEGA * RI

    def transient(t, steps=2000):
        if t <= 0:
            return np.zeros(n)
        h = t / steps
        eye = np.eye(m)
        implicit = np.linalg.inv(eye - h * nu * lap)
        lhs = eye - 0.5 * h * nu * lap
        cn = np.linalg.solve(lhs, eye + 0.5 * h * nu * lap)
        cn_bc = np.linalg.solve(lhs, h * nu * bc)
        u = np.zeros(m)
        for s in range(steps):
            u = implicit @ (u + h * nu * bc) if s < 20 else cn @ u + cn_bc
        return np.concatenate([[OMEGA * RI], u, [0.0]])

    return r, (lambda x: a * x + b / x), transient


def main():
    run, every = sys.argv[1], float(sys.argv[2])
    bins = int(sys.argv[3]) if len(sys.argv) > 3 else 8
    nu = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-6
    r, steady, transient = profiles(nu)
    scale = OMEGA * RI
    for f in sorted(glob.glob(os.path.join(run, "particles_*.vtp"))):
        t = int(re.findall(r"particles_(\d+)\.vtp", f)[0]) * every
        if t == 0:
            continue
        d = read_vtp(f)
        x, y = d["points"][:, 0], d["points"][:, 1]
        v = d["velocity"]
        rr = np.hypot(x, y)
        vt = (-y * v[:, 0] + x * v[:, 1]) / rr
        vr = (x * v[:, 0] + y * v[:, 1]) / rr
        ue = np.interp(rr, r, transient(t))
        k = np.clip(((rr - RI) / (RO - RI) * bins).astype(int), 0, bins - 1)
        means = " ".join(f"{vt[k == i].mean() / scale:.3f}/{ue[k == i].mean() / scale:.3f}"
                         for i in range(bins) if np.any(k == i))
        print(f"t = {t:6.1f}  vs transient {np.sqrt(np.mean((vt - ue) ** 2)) / scale:.4f}"
              f"  vs steady {np.sqrt(np.mean((vt - steady(rr)) ** 2)) / scale:.4f}"
              f"  v_r rms {np.sqrt(np.mean(vr ** 2)) / scale:.4f}  bins {means}")


if __name__ == "__main__":
    main()
