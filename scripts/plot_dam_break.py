"""Plots of `curvsph validate dam_break_3d`: pressures P1-P8 and water heights H1-H4 of every
run against the MARIN experiment (SPHERIC test 2), from RUN/dam_break_comparison.csv."""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out, runs = sys.argv[1], sys.argv[2:]
data = {}
for run in runs:
    path = os.path.join(out, run, "dam_break_comparison.csv")
    if os.path.exists(path):
        rows = list(csv.DictReader(open(path)))
        data[run] = {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else None
data = {k: v for k, v in data.items() if v}
if not data:
    sys.exit("no dam_break_comparison.csv to plot")

longest = max(data, key=lambda r: data[r]["time"][-1])


def plot(names, ylabel, fname, scale=1.0):
    fig, axes = plt.subplots(len(names) // 2, 2, figsize=(11, 2.4 * len(names) // 2), sharex=True)
    for ax, n in zip(axes.flat, names):
        d = data[longest]
        ax.plot(d["time"], [v * scale for v in d[n + "_exp"]], "k-", lw=0.8, label="experiment")
        for run, d in data.items():
            vals = [0.0 if (math.isnan(v) and n.startswith("P")) else v * scale for v in d[n]]
            ax.plot(d["time"], vals, lw=1.0, label=f"SPH {run}")
        ax.set_title(n, fontsize=9)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("t (s)")
    axes.flat[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, fname), dpi=110)


plot([f"P{k}" for k in range(1, 9)], "p (kPa)", "pressures.png", 1e-3)
plot([f"H{k}" for k in range(1, 5)], "height (m)", "heights.png")
