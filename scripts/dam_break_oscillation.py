"""Diagnostics of the post-impact pressure oscillation of the 3-D dam break (issue 5).

Usage: dam_break_oscillation.py OUT.png EXPERIMENT.dat LABEL=RUN_DIR [LABEL=RUN_DIR ...]

Each RUN_DIR holds probes.csv and, when the run wrote snapshots, series.pvd + particles_*.vtp.
From the snapshots: the energy E = kinetic + potential (m g z) + internal, the internal energy
of the linear EOS being m c0^2 (ln(rho/rho0) + rho0/rho - 1) (de = p/rho^2 drho); the number
of particles within 0.1 dx of the box obstacle (where the optional wall force acts) and the
most negative pressure within 2h of the box. Prints one table row per run and plots P1, P3,
E - E(first snapshot) and the near-box counts against time.
"""
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp import read_vtp  # noqa: E402

C0, RHO0, G = 40.0, 998.0, 9.81
BOX_LO = np.array([0.6635, 0.295, 0.0])
BOX_HI = np.array([0.8245, 0.698, 0.161])


def probes(run):
    rows = list(csv.DictReader(open(os.path.join(run, "probes.csv"))))
    out = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    return out


def snapshots(run, dx):
    pvd = os.path.join(run, "series.pvd")
    if not os.path.exists(pvd):
        return None
    rows = []
    text = open(pvd).read()
    for t, part, f in re.findall(r'timestep="([^"]+)" group="" part="(\d)" file="([^"]+)"', text):
        if part != "0" or "unstable" in f:
            continue
        d = read_vtp(os.path.join(run, f))
        x, v, m, rho, p = d["points"], d["velocity"], d["mass"], d["density"], d["pressure"]
        energy = (0.5 * np.sum(m * np.sum(v * v, axis=1)) + np.sum(m * G * x[:, 2]) +
                  np.sum(m * C0 * C0 * (np.log(rho / RHO0) + RHO0 / rho - 1)))
        dbox = np.linalg.norm(np.maximum(np.maximum(BOX_LO - x, x - BOX_HI), 0), axis=1)
        near = dbox < 4 * dx  # 2h at h = 2 dx
        rows.append((float(t), energy, int(np.sum(dbox < 0.1 * dx)),
                     float(p[near].min()) if near.any() else math.nan))
    rows.sort()
    return np.array(rows) if rows else None


def main():
    out, exp_path, specs = sys.argv[1], sys.argv[2], sys.argv[3:]
    exp = np.loadtxt(exp_path, skiprows=1)
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    t_lo, t_hi = 1e9, -1e9
    print("| run | t | P1 max (Pa) | P3 min (Pa) | E(end) - E(start) (J) | "
          "max particles within 0.1 dx of the box | min p within 2h of the box (Pa) |")
    print("|---|---|---|---|---|---|---|")
    for spec in specs:
        label, run = spec.split("=", 1)
        dx = 0.55 / 15
        log = os.path.join(run, "log.txt")
        if os.path.exists(log):
            m = re.search(r"dx = ([0-9.e-]+)", open(log).read())
            if m:
                dx = float(m.group(1))
        pr = probes(run)
        t = pr["time"]
        t_lo, t_hi = min(t_lo, t[0]), max(t_hi, t[-1])
        p1 = np.nan_to_num(pr["P1.p_wall"])
        p3 = np.nan_to_num(pr["P3.p_wall"])
        axes[0].plot(t, p1 * 1e-3, lw=1, label=label)
        axes[1].plot(t, p3 * 1e-3, lw=1, label=label)
        sn = snapshots(run, dx)
        de, near_max, pmin = math.nan, math.nan, math.nan
        if sn is not None:
            axes[2].plot(sn[:, 0], sn[:, 1] - sn[0, 1], lw=1, label=label)
            axes[3].plot(sn[:, 0], sn[:, 2], lw=1, label=label)
            de, near_max, pmin = sn[-1, 1] - sn[0, 1], sn[:, 2].max(), np.nanmin(sn[:, 3])
        print(f"| {label} | {t[0]:.3f}-{t[-1]:.3f} | {p1.max():.0f} | {p3.min():.0f} | "
              f"{de:.2f} | {near_max:.0f} | {pmin:.0f} |")
    sel = (exp[:, 0] >= t_lo) & (exp[:, 0] <= t_hi)
    axes[0].plot(exp[sel, 0], exp[sel, 1] * 1e-3, "k-", lw=0.8, label="experiment")
    axes[1].plot(exp[sel, 0], exp[sel, 3] * 1e-3, "k-", lw=0.8, label="experiment")
    axes[0].set_ylabel("P1 (kPa)")
    axes[1].set_ylabel("P3 (kPa)")
    axes[2].set_ylabel("E - E(start) (J)")
    axes[3].set_ylabel("particles < 0.1 dx\nfrom the box")
    axes[3].set_xlabel("t (s)")
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
