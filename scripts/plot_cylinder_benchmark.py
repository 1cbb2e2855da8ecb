"""Force histories of `curvsph validate cylinder_benchmark`.
Usage: plot_cylinder_benchmark.py OUT_DIR

Reads OUT_DIR/histories.csv (run,t,cd,cl) and OUT_DIR/dp_histories.csv (run,t,dp); writes
OUT_DIR/histories.png: C_D, C_L and dp against time for every run, the raw samples (thin) and
their running mean over 0.5 s (thick; the acoustic noise of the weakly compressible fluid rides
on the raw signal), with the 2D-1 reference values (John & Matthies 2001) dashed."""
import csv
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

REFERENCE = {"cd": 5.57953523384, "cl": 0.010618948146, "dp": 0.11752016697}


def load(path, field):
    runs = OrderedDict()
    with open(path) as f:
        for row in csv.DictReader(f):
            t, v = runs.setdefault(row["run"], ([], []))
            t.append(float(row["t"]))
            v.append(float(row[field]))
    return {k: (np.array(t), np.array(v)) for k, (t, v) in runs.items()}


def running_mean(t, v, width):
    if len(t) < 2:
        return v
    step = (t[-1] - t[0]) / (len(t) - 1)
    n = min(len(v), max(1, int(round(width / step))))
    # Normalised by the window's count, so the ends (a cut window) are not pulled to zero.
    kernel = np.ones(n)
    return np.convolve(v, kernel, mode="same") / np.convolve(np.ones(len(v)), kernel, mode="same")


def main():
    out = sys.argv[1]
    panels = [("cd", "histories.csv", "C_D"), ("cl", "histories.csv", "C_L"),
              ("dp", "dp_histories.csv", "Δp = p(0.15, 0.2) − p(0.25, 0.2)")]
    fig, axes = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
    for ax, (field, name, title) in zip(axes, panels):
        data = load(os.path.join(out, name), field)
        for i, (run, (t, v)) in enumerate(data.items()):
            color = f"C{i}"
            ax.plot(t, v, lw=0.3, color=color, alpha=0.35)
            ax.plot(t, running_mean(t, v, 0.5), lw=1.4, color=color, label=run)
        if any(run.startswith("re20") or "_re20" in run for run in data):
            ax.axhline(REFERENCE[field], color="k", ls="--", lw=1, label="2D-1 reference")
        ax.set_ylabel(title)
        ax.grid(alpha=0.3)
        # The start-up (pressure waves of the ramp) reaches far beyond the steady values.
        ref = REFERENCE[field]
        span = {"cd": (0, 2.5 * ref), "cl": (-0.6, 0.6), "dp": (-0.2, 0.4)}[field]
        ax.set_ylim(*span)
    axes[0].legend(fontsize=7, ncol=2)
    axes[0].set_title("Cylinder in a channel (Schäfer & Turek 2D-1, Re = 20)\n"
                      "raw samples (thin) and running mean over 0.5 s (thick)")
    axes[-1].set_xlabel("t (s)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "histories.png"), dpi=110)


if __name__ == "__main__":
    main()
