"""Plots of `curvsph validate moving_cylinder`. Usage: plot_moving_cylinder.py OUT_DIR"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def load(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def main():
    out = sys.argv[1]
    g = load(os.path.join(out, "galilean.csv"))
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(g["t_mid"], g["cd_towed"], "o-", label="towed at U, fluid at rest")
    ax.plot(g["t_mid"], g["cd_fixed"], "s--", label="still, fluid started at -U")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("C_D (mean over windows of D/(2U))")
    ax.set_title("Galilean check, Re = 20")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "galilean.png"), dpi=120)
    o = load(os.path.join(out, "oscillating.csv"))
    fig, ax = plt.subplots(figsize=(6, 4))
    # Acoustic noise of the weakly compressible fluid rides on the force: a running mean over
    # a twentieth of the period shows the hydrodynamic part; the start-up spike is cut off.
    t, fx = o["t"], o["fx"]
    keep = t > 0.05 * t[-1]
    width = max(1, int(round(len(t) / t[-1] * 0.25)))
    smooth = np.convolve(fx, np.ones(width) / width, mode="same")
    ax.plot(t[keep], fx[keep], lw=0.4, color="0.7", label="F_x on the cylinder (momentum balance)")
    ax.plot(t[keep], smooth[keep], lw=1.2, color="C0", label="running mean over 0.25 s")
    ax2 = ax.twinx()
    ax2.plot(o["t"], o["u_cylinder"], "k--", lw=1, label="cylinder velocity")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("F_x (N/m)")
    ax2.set_ylabel("u (m/s)")
    ax.set_title("In-line oscillating cylinder, Re = 100, KC = 5")
    ax.grid(alpha=0.3)
    fig.legend(loc="lower center", fontsize=7, ncol=3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "oscillating.png"), dpi=120)


if __name__ == "__main__":
    main()
