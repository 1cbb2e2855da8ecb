"""Plots of `curvsph validate hydrostatic_tank` (Calderon et al. Figs. 9-12): reduced kinetic
energy and pressure error against t sqrt(g/H) for every run (solid: geometric Shepard factor,
dashed: volume, dotted: the mirror-ghost comparison row, dash-dot: the h/dx = 4 comparison rows
with one change to the case), the pressure profile against depth at the end, and the particles near the
right-hand corner at the end (coloured by p - p_hydrostatic).

The last two read RUN/hydrostatic_profile.csv, a per-particle dump that is not committed (it
is written by the run and ignored by git): a run reused from its committed metrics has none,
and a figure without any profile keeps its committed PNG (delete RUN/ to redo the run)."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

out = sys.argv[1]
runs = list(csv.DictReader(open(os.path.join(out, "hydrostatic_tank.csv"))))
colors = {}
palette = plt.rcParams["axes.prop_cycle"].by_key()["color"]


def label(r):
    variant = r.get("variant") or ""
    return f"N={r['particles']}, h/dx={r['h_over_dx']}, {r['shepard']}" + (
        f" + {variant}" if variant else "")


def color(r):
    key = (r["dx"], r["h_over_dx"], r.get("variant") or "")
    if key not in colors:
        colors[key] = palette[len(colors) % len(palette)]
    return colors[key]


def profile(r):
    """The per-particle profile at the end of run r, or None when the run left none here."""
    path = os.path.join(out, r["run"], "hydrostatic_profile.csv")
    if not os.path.exists(path):
        print(f"plot_hydrostatic_tank: {path} missing (not committed; rerun to regenerate)",
              file=sys.stderr)
        return None
    return np.genfromtxt(path, delimiter=",", names=True)


def history(r):
    path = os.path.join(out, r["run"], "hydrostatic_history.csv")
    d = np.genfromtxt(path, delimiter=",", names=True)
    return np.atleast_1d(d)


for field, fname, ylabel in [("kinetic_energy", "kinetic_energy.png", "KE / (M g H)"),
                             ("pressure_l2_error", "pressure_error.png",
                              "L2(p - ρ0 g (H - y)) / (ρ0 g H)")]:
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for r in runs:
        d = history(r)
        y = np.maximum(d[field], 1e-14)
        ls = "-." if r.get("variant") else {"geometric": "-", "ghost": ":"}.get(r["shepard"], "--")
        ax.semilogy(d["reduced_time"], y, ls, color=color(r), lw=1.2, label=label(r))
        if r["unstable"] == "1":
            ax.plot(d["reduced_time"][-1], y[-1], "x", color=color(r), ms=8)
    ax.set_xlabel("t √(g/H)")
    ax.set_ylabel(ylabel)
    ax.set_title("Hydrostatic tank: solid geometric γ, dashed volume γ, dotted ghosts,\n"
                 "dash-dot: h/dx = 4 with one change to the case (x: failure)", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, fname), dpi=120)
    plt.close(fig)

# Pressure profile at the end for the N ~ 10^4 runs (and the finest geometric one).
fig, ax = plt.subplots(figsize=(5.5, 5))
shown = [r for r in runs if r["h_over_dx"] == "2"]
finest = max(shown, key=lambda r: int(r["particles"]))
pick = [r for r in shown if r["dx"] == shown[0]["dx"]] + [finest]
seen = set()
drawn = 0
for r in pick:
    if r["run"] in seen:
        continue
    seen.add(r["run"])
    d = profile(r)
    if d is None:
        continue
    drawn += 1
    ax.plot(d["p"] / 1000, d["y"], ".", ms=1.5, alpha=0.4, color=color(r) if r["shepard"] ==
            "geometric" else "gray", label=label(r) + f", t√(g/H)={float(r['t_end_reached']):.1f}")
y = np.linspace(0, 0.5, 50)
ax.plot(998 * 9.81 * (0.5 - y) / 1000, y, "k-", lw=1, label="ρ0 g (H - y)")
ax.set_xlabel("p [kPa]")
ax.set_ylabel("y [m]")
ax.set_title("Pressure against depth at the end")
ax.legend(fontsize=7, markerscale=6)
ax.grid(True, alpha=0.3)
fig.tight_layout()
if drawn:
    fig.savefig(os.path.join(out, "pressure_profile.png"), dpi=120)
plt.close(fig)

# Fig. 9: the right-hand corner at the end, geometric against volume (N ~ 10^4), and ghosts.
base = [r for r in runs if r["dx"] == runs[0]["dx"] and r["h_over_dx"] == "2"]
base = [(r, d) for r, d in ((r, profile(r)) for r in base) if d is not None]
if not base:
    sys.exit(0)
fig, axes = plt.subplots(1, len(base), figsize=(5 * len(base), 4.2), squeeze=False)
for ax, (r, d) in zip(axes[0], base):
    sel = (d["x"] > 0.75) & (d["y"] > 0.3)
    sc = ax.scatter(d["x"][sel], d["y"][sel], c=(d["p"] - d["p_exact"])[sel] / (998 * 9.81 * 0.5),
                    s=6, cmap="coolwarm", vmin=-0.02, vmax=0.02)
    ax.set_aspect("equal")
    ax.set_xlim(0.75, 1.0)
    ax.set_ylim(0.3, 0.62)
    walls = "mirror ghosts" if r["shepard"] == "ghost" else f"{r['shepard']} γ"
    ax.set_title(f"{walls}, t√(g/H) = {float(r['t_end_reached']):.1f}")
    fig.colorbar(sc, ax=ax, label="(p - ρ0 g (H - y)) / (ρ0 g H)")
fig.tight_layout()
fig.savefig(os.path.join(out, "corner.png"), dpi=120)
plt.close(fig)
