#!/usr/bin/env python3
"""Splits the Couette velocity error of a run into the error of the mean azimuthal profile and
the particle scatter around it, at every VTK output (issue #4 diagnosis).

    /usr/bin/python3 scripts/couette_split.py RUN_DIR [RUN_DIR ...]

For each output time: total = sqrt(mean (v_theta,i - v(r_i))^2) / (omega R_i) (Barker eq. 25
with the square); the particles are binned in radius (bins of width dx); profile = the same norm
of (bin mean of v_theta - v) and scatter = the norm of (v_theta,i - bin mean), so that
total^2 = profile^2 + scatter^2 exactly. Also the rms radial velocity, and the density of the
bulk (particles more than 2h = 2.6 dx from both walls): mean and std of rho/rho0, and of the
density minus the exact radial balance rho(p(r)) (Tait, c0 = 0.25, p0 = 2.5).
R_i, R_o, omega, rho0, c0 are cases/couette.yaml's.
"""
import glob
import json
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from vtp import read_vtp  # noqa: E402

RI, RO, OMEGA, RHO0, C0, GAMMA, P0 = 0.025, 0.040, 1.0, 1000.0, 0.25, 7.0, 2.5
UREF = OMEGA * RI
A = -OMEGA * RI**2 / (RO**2 - RI**2)
B = OMEGA * RI**2 * RO**2 / (RO**2 - RI**2)


def v_exact(r):
    return A * r + B / r


def main():
    for run in sys.argv[1:]:
        files = sorted(glob.glob(os.path.join(run, "particles_*.vtp")),
                       key=lambda f: int(re.findall(r"(\d+)", os.path.basename(f))[-1]))
        log = open(os.path.join(run, "log.txt")).read()
        dx = float(re.search(r"dx = ([0-9.e-]+)", log).group(1))
        print(f"# {run}  dx = {dx}")
        print("k total profile scatter vr_rms bulk_rho_mean bulk_rho_std bulk_rho_std_vs_balance")
        for k, f in enumerate(files):
            d = read_vtp(f)
            x = d["points"][:, :2].astype(float)
            v = d["velocity"][:, :2].astype(float) if "velocity" in d else d["vel"][:, :2]
            rho = d["density"].astype(float) if "density" in d else d["rho"].astype(float)
            r = np.hypot(x[:, 0], x[:, 1])
            er = x / r[:, None]
            et = np.stack([-er[:, 1], er[:, 0]], axis=1)
            vt = (v * et).sum(1)
            vr = (v * er).sum(1)
            e = vt - v_exact(r)
            nb = max(1, round((RO - RI) / dx))
            b = np.clip(((r - RI) / (RO - RI) * nb).astype(int), 0, nb - 1)
            mean_e = np.array([e[b == q].mean() if np.any(b == q) else 0.0 for q in range(nb)])
            prof = mean_e[b]
            total = math.sqrt((e**2).mean()) / UREF
            profile = math.sqrt((prof**2).mean()) / UREF
            scatter = math.sqrt(((e - prof)**2).mean()) / UREF
            bulk = (r - RI > 2.6 * dx) & (RO - r > 2.6 * dx)
            # exact radial balance: p(r) from dp/dr = rho v^2 / r, mean-free up to a constant
            rr = np.linspace(RI, RO, 2001)
            dp = np.concatenate([[0], np.cumsum(RHO0 * v_exact(rr[1:])**2 / rr[1:] * np.diff(rr))])
            pb = np.interp(r, rr, dp)
            rho_bal = RHO0 * (1 + (pb - pb[bulk].mean()) / (RHO0 * C0**2))
            dev = rho / RHO0 - rho_bal / RHO0
            print(f"{k} {total:.5f} {profile:.5f} {scatter:.5f} {math.sqrt((vr**2).mean())/UREF:.5f} "
                  f"{(rho[bulk]/RHO0).mean():.6f} {(rho[bulk]/RHO0).std():.6f} {dev[bulk].std():.6f}")


if __name__ == "__main__":
    main()
