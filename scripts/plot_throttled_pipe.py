"""Plots of the throttled pipe (Barker & Neethling §4.1, Figs. 8-9).

    plot_throttled_pipe.py OUT_DIR RUN_DIR

OUT_DIR: docs/validation/throttled_pipe (throttled_pipe.csv, dx_*/ run directories);
RUN_DIR: the run whose last snapshot and profiles are drawn. Writes velocity_field.png
(velocity magnitude with the walls drawn, Fig. 8b), profiles.png (midline profiles against
eq. 48, Fig. 9) and flux.png (Q(x) and the flux history). `plot_field` is shared with
scripts/plot_demo.py.
"""
import csv
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp import read_vtp  # noqa: E402


def last_snapshot(run_dir):
    """Path of the last particles_*.vtp listed in series.pvd (or found in run_dir)."""
    pvd = os.path.join(run_dir, "series.pvd")
    files = []
    if os.path.exists(pvd):
        # Part 0 holds the particles (part 1: ghosts / wall elements).
        files = [f for f in re.findall(r'file="([^"]+)"', open(pvd).read())
                 if os.path.basename(f).startswith("particles_")]
    if not files:
        files = sorted(f for f in os.listdir(run_dir) if re.match(r"particles_\d+\.vtp$", f))
    if not files:
        raise FileNotFoundError(f"no particle snapshot in {run_dir}")
    return os.path.join(run_dir, files[-1])


def read_csv(path):
    rows = list(csv.DictReader(open(path)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def plot_field(plt, run_dir, png, title):
    """Particles coloured by |v|, walls (from the analysis' midline CSV) in black."""
    snap = read_vtp(last_snapshot(run_dir))
    x = snap["points"][:, 0]
    y = snap["points"][:, 1]
    v = snap["velocity"]
    speed = np.hypot(v[:, 0], v[:, 1])
    walls = read_csv(os.path.join(run_dir, "throttled_pipe_midline_x.csv"))
    lo = walls["y"] - walls["half_width"]
    hi = walls["y"] + walls["half_width"]
    span = x.max() - x.min()
    fig, ax = plt.subplots(figsize=(8.0, 3.9))
    size = max(1.0, 9000.0 / len(x))
    sc = ax.scatter(x, y, c=speed, s=size, cmap="viridis", linewidths=0)
    ax.plot(walls["x"], lo, "k-", lw=1.6)
    ax.plot(walls["x"], hi, "k-", lw=1.6)
    ax.fill_between(walls["x"], lo, lo.min() - 0.05 * span, color="0.75")
    ax.fill_between(walls["x"], hi, hi.max() + 0.05 * span, color="0.75")
    ax.set_xlim(walls["x"].min(), walls["x"].max())
    ax.set_ylim(lo.min() - 0.03 * span, hi.max() + 0.03 * span)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(title, fontsize=9)
    fig.colorbar(sc, ax=ax, label="|v| [m/s]", shrink=0.8)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)


def main():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out, run = sys.argv[1], sys.argv[2]
    tag = os.path.basename(os.path.normpath(run)).replace("_", " = ")
    plot_field(plt, run, os.path.join(out, "velocity_field.png"),
               f"Throttled pipe, velocity magnitude at the end ({tag}), NURBS walls, mirror_beta")

    mx = read_csv(os.path.join(run, "throttled_pipe_midline_x.csv"))
    my = read_csv(os.path.join(run, "throttled_pipe_midline_y.csv"))
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    a.plot(mx["x"], mx["vx"], "o", ms=3, label="SPH, v_x on the midline")
    a.plot(mx["x"], mx["vx_eq48"], "k-", label="eq. 48 (reference: seam section)")
    a.plot(mx["x"], mx["vx_lubrication"], "r--", lw=1, label="3Q/(4R(x)) (lubrication)")
    a.plot(mx["x"], mx["vy"], "s", ms=2, color="tab:green", label="SPH, v_y on the midline")
    a.set_xlabel("x [m]")
    a.set_ylabel("velocity [m/s]")
    a.set_title("(a) along the midline (Barker Fig. 9a)", fontsize=9)
    a.legend(fontsize=7)
    a.grid(alpha=0.3)
    b.plot(my["vx"], my["y"], "o", ms=3, label="SPH, v_x")
    b.plot(my["vx_eq48"], my["y"], "k-", label="eq. 48")
    b.set_xlabel("v_x [m/s]")
    b.set_ylabel("y [m]")
    b.set_title(f"(b) across the throat x = {my['x'][0]:.4g} (Fig. 9b)", fontsize=9)
    b.legend(fontsize=7)
    b.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles.png"), dpi=120)
    plt.close(fig)

    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 3.8))
    for d in sorted(os.listdir(out)):
        f = os.path.join(out, d, "throttled_pipe_flux.csv")
        if not d.startswith("dx_") or not os.path.exists(f):
            continue
        q = read_csv(f)
        a.plot(q["x"], q["flux"] / q["flux"].mean(), "o-", ms=3, label=d.replace("_", " = "))
        h = read_csv(os.path.join(out, d, "throttled_pipe_history.csv"))
        # The particle flux sum (no interpolation), where the history has it.
        q_t = h["flux_particles"] if "flux_particles" in h else h["reynolds"] * 1e-5
        b.plot(h["time"], q_t / 3.05e-4 - 1, "o-", ms=3, label=d.replace("_", " = "))
    a.axhspan(0.985, 1.015, color="0.9", label="+-1.5 % (variation 0.03)")
    a.set_xlabel("x [m]")
    a.set_ylabel("Q(x) / mean Q")
    a.set_title("flux across each section (eq. 47)", fontsize=9)
    a.legend(fontsize=7)
    a.grid(alpha=0.3)
    b.set_xlabel("t [s]")
    b.axhspan(-0.03, 0.03, color="0.9", label="+-3 % (issue 36)")
    b.set_ylabel("sum V u_x / L_x / Q_ref - 1")
    b.set_title("flux history against the lattice Boltzmann (Q_ref = 3.05e-4)", fontsize=9)
    b.legend(fontsize=7)
    b.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "flux.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
