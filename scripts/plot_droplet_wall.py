"""Plots of the drop on a NURBS wall (Barker & Neethling §4.2, Fig. 10).

    plot_droplet_wall.py OUT_DIR

OUT_DIR: docs/validation/droplet_wall (droplet_wall.csv and theta_*/ run directories, each with
droplet_particles.csv, droplet_fit.csv, contact_angle_history.csv). Writes angles.png (measured
against imposed angle), shapes.png (final particles with the fitted circles, Fig. 10) and
history.png (measured angle against time).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path):
    rows = list(csv.DictReader(open(path)))
    out = {}
    for k in rows[0]:
        try:
            out[k] = np.array([float(r[k]) for r in rows])
        except ValueError:
            out[k] = [r[k] for r in rows]
    return out


out = sys.argv[1]
summary = read_csv(os.path.join(out, "droplet_wall.csv"))
imposed = summary["imposed_deg"]

fig, ax = plt.subplots(figsize=(5, 5))
lim = [0, 180]
ax.plot(lim, lim, "k-", lw=0.8, label="measured = imposed")
ax.fill_between(lim, [v - 5 for v in lim], [v + 5 for v in lim], color="0.85", label="±5°")
ax.plot(imposed, summary["measured_left_deg"], "o", mfc="none", label="left contact point")
ax.plot(imposed, summary["measured_right_deg"], "x", label="right contact point")
ax.plot(imposed, summary["initial_deg"], "s", color="0.5", ms=4, label="initial shape (t = 0)")
ax.set_xlabel("imposed contact angle (deg)")
ax.set_ylabel("measured contact angle (deg)")
ax.set_xlim(lim)
ax.set_ylim(lim)
ax.legend(loc="upper left", fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(out, "angles.png"), dpi=120)

n = len(imposed)
fig, axes = plt.subplots(n, 1, figsize=(7, 2.2 * n), sharex=True)
axes = np.atleast_1d(axes)
for ax, theta in zip(axes, imposed):
    run = os.path.join(out, f"theta_{int(theta)}")
    p = read_csv(os.path.join(run, "droplet_particles.csv"))
    drop = p["drop"] > 0
    ax.scatter(p["x"][~drop] * 1e3, p["y"][~drop] * 1e3, s=2, color="tab:blue", lw=0)
    ax.scatter(p["x"][drop] * 1e3, p["y"][drop] * 1e3, s=2, color="tab:red", lw=0)
    fit_path = os.path.join(run, "droplet_fit.csv")
    if os.path.exists(fit_path) and os.path.getsize(fit_path) > 0:
        rows = list(csv.DictReader(open(fit_path)))
        for r in rows:
            cx, cy, rad = (float(r[k]) * 1e3 for k in ("center_x", "center_y", "radius"))
            phi = np.linspace(0, 2 * np.pi, 400)
            ax.plot(cx + rad * np.cos(phi), cy + rad * np.sin(phi), "k-", lw=0.7)
            ax.plot(float(r["contact_x"]) * 1e3, float(r["contact_y"]) * 1e3, "ko", ms=3)
            ax.annotate(f"{float(r['theta_deg']):.1f}°",
                        (float(r["contact_x"]) * 1e3, float(r["contact_y"]) * 1e3),
                        textcoords="offset points", xytext=(0, -12), fontsize=8, ha="center")
    ax.set_title(f"imposed {int(theta)}°", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlim(-3, 3)
    ax.set_ylim(-0.7, 1.5)
    ax.set_ylabel("y (mm)")
axes[-1].set_xlabel("x (mm)")
fig.tight_layout()
fig.savefig(os.path.join(out, "shapes.png"), dpi=120)

fig, ax = plt.subplots(figsize=(6, 4))
for theta in imposed:
    h = read_csv(os.path.join(out, f"theta_{int(theta)}", "contact_angle_history.csv"))
    line, = ax.plot(h["time"], (h["left_deg"] + h["right_deg"]) / 2, label=f"imposed {int(theta)}°")
    ax.axhline(theta, color=line.get_color(), ls=":", lw=0.8)
ax.set_xlabel("t (s)")
ax.set_ylabel("measured angle, mean of both sides (deg)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(out, "history.png"), dpi=120)
