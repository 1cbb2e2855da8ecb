#!/usr/bin/env python3
"""Plot of `curvsph validate throughput`: particle-steps per second per configuration at 1
and 2 threads (left) and the split of a step by phase at 2 threads (right).
Usage: plot_throughput.py DIR  (reads DIR/throughput.csv, writes DIR/throughput.png)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/throughput.csv")))
configs = list(dict.fromkeys(r["config"] for r in rows))
rate = {(r["config"], int(r["threads"])): float(r["particle_steps_per_second"]) for r in rows}

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5))
w = 0.38
for k, t in enumerate((1, 2)):
    ax1.bar([i + (k - 0.5) * w for i in range(len(configs))],
            [rate.get((c, t), 0) for c in configs], w, label=f"{t} thread{'s' if t > 1 else ''}")
ax1.axhline(5e5, color="k", ls="--", lw=1, label="target (a), 2 threads")
ax1.axhspan(3.2e5, 3.6e5, color="grey", alpha=0.3, label="DualSPHysics 5.4, 2 threads")
ax1.set_xticks(range(len(configs)))
ax1.set_xticklabels(configs, rotation=30, ha="right")
ax1.set_ylabel("particle-steps per second")
ax1.set_yscale("log")
ax1.legend(fontsize=8)
ax1.set_title("throughput (shared 2-core machine)")

phases = ["neighbors", "boundary_prepass", "boundary_terms", "density", "forces", "integrate"]
two = {r["config"]: r for r in rows if int(r["threads"]) == 2}
bottom = [0.0] * len(configs)
for ph in phases:
    frac = [float(two[c][ph]) / float(two[c]["seconds"]) if c in two else 0 for c in configs]
    ax2.bar(range(len(configs)), frac, 0.6, bottom=bottom, label=ph)
    bottom = [b + f for b, f in zip(bottom, frac)]
ax2.set_xticks(range(len(configs)))
ax2.set_xticklabels(configs, rotation=30, ha="right")
ax2.set_ylabel("share of a step (2 threads)")
ax2.set_ylim(0, 1.05)
ax2.legend(fontsize=8)
fig.tight_layout()
fig.savefig(f"{out}/throughput.png", dpi=110)
