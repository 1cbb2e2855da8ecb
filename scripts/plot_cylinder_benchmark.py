"""Force histories of `curvsph validate cylinder_benchmark`.
Usage: plot_cylinder_benchmark.py OUT_DIR

Reads OUT_DIR/histories.csv (run,t,cd,cl) and OUT_DIR/dp_histories.csv (run,t,dp); writes
OUT_DIR/histories_re20.png: C_D, C_L and dp against time for every 2D-1 run, the raw samples
(thin) and their running mean over 0.5 s (thick; the acoustic noise of the weakly compressible
fluid rides on the raw signal), with the 2D-1 reference values (John & Matthies 2001) dashed;
and OUT_DIR/histories_re100.png: the raw histories of the 2D-2 runs with the reference maxima."""
import csv
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

REFERENCE = {"cd": 5.57953523384, "cl": 0.010618948146, "dp": 0.11752016697}
REFERENCE_MAX = {"cd": (3.23,), "cl": (1.0, -1.0)}  # 2D-2: C_D,max, C_L max and min


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


def plot(out, group, runs, panels):
    fig, axes = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
    for ax, (field, data, title) in zip(axes, panels):
        for i, run in enumerate(r for r in data if r in runs):
            t, v = data[run]
            color = f"C{i}"
            if group == "re20":
                ax.plot(t, v, lw=0.3, color=color, alpha=0.35)
                ax.plot(t, running_mean(t, v, 0.5), lw=1.4, color=color, label=run)
            else:  # shedding at about 3 Hz: the raw samples, no running mean
                ax.plot(t, v, lw=0.6, color=color, label=run)
        if group == "re20":
            ax.axhline(REFERENCE[field], color="k", ls="--", lw=1, label="2D-1 reference")
            # The start-up (pressure waves of the ramp) reaches far beyond the steady values.
            span = {"cd": (0, 2.5 * REFERENCE[field]), "cl": (-0.6, 0.6), "dp": (-0.2, 0.4)}
            ax.set_ylim(*span[field])
        else:
            for level in REFERENCE_MAX.get(field, ()):
                ax.axhline(level, color="k", ls="--", lw=1, label="2D-2 reference maximum")
        ax.set_ylabel(title)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7, ncol=2)
    axes[0].set_title("Cylinder in a channel (Schäfer & Turek 2D-1, Re = 20)\n"
                      "raw samples (thin) and running mean over 0.5 s (thick)" if group == "re20"
                      else "Cylinder in a channel (Schäfer & Turek 2D-2, Re = 100)")
    axes[-1].set_xlabel("t (s)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"histories_{group}.png"), dpi=90)


def main():
    out = sys.argv[1]
    forces_cd = load(os.path.join(out, "histories.csv"), "cd")
    forces_cl = load(os.path.join(out, "histories.csv"), "cl")
    dp = load(os.path.join(out, "dp_histories.csv"), "dp")
    panels = [("cd", forces_cd, "C_D"), ("cl", forces_cl, "C_L"),
              ("dp", dp, "Δp = p(0.15, 0.2) − p(0.25, 0.2)")]
    for group in ("re20", "re100"):
        runs = [r for r in forces_cd if group + "_" in r]
        if runs:
            plot(out, group, runs, panels)


if __name__ == "__main__":
    main()
