"""Plots of `curvsph validate poiseuille`. Usage: plot_poiseuille.py OUT_DIR"""
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
    d = load(os.path.join(out, "run", "poiseuille_profile.csv"))
    o = np.argsort(d["y"])
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.plot(d["u"] * 1e3, d["y"] * 1e3, ".", ms=4, label="SPH (every particle)")
    ax.plot(d["u_exact"][o] * 1e3, d["y"][o] * 1e3, "k-", lw=1, label="parabola")
    ax.set_xlabel("u (mm/s)")
    ax.set_ylabel("y (mm)")
    ax.set_title("Plane Poiseuille flow at the end")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profile.png"), dpi=120)
    plt.close(fig)
    e = load(os.path.join(out, "run", "poiseuille_error.csv"))
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.semilogy(e["time"], e["velocity_l2_error"])
    ax.set_xlabel("t (s)")
    ax.set_ylabel("relative L2 velocity error")
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error_vs_time.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
