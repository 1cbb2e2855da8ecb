"""Plots of `curvsph validate oscillating_cylinder`.
Usage: plot_oscillating_cylinder.py OUT_DIR PERIOD

Reads OUT_DIR/force_histories.csv (run,t,f_over_rho_u2_d), OUT_DIR/reference.csv (Morison with
Dütsch et al.'s C_d = 2.09, C_i = 1.45 over one period) and data/dutsch1998's digitised curve
(found from this script's folder); writes OUT_DIR/oscillating_cylinder.png: top, the in-line
force of every run over the whole run against the reference repeated period by period; bottom,
the last period of each run (its raw samples thin, a running mean over a fortieth of the period
thick: the acoustic noise of the weakly compressible fluid rides on the raw force) against the
reference and the digitised points."""
import csv
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def main():
    out, period = sys.argv[1], float(sys.argv[2])
    runs = OrderedDict()
    for row in read_rows(os.path.join(out, "force_histories.csv")):
        t, f = runs.setdefault(row["run"], ([], []))
        t.append(float(row["t"]))
        f.append(float(row["f_over_rho_u2_d"]))
    ref = read_rows(os.path.join(out, "reference.csv"))
    rt = np.array([float(r["t_over_T"]) for r in ref])
    rf = np.array([float(r["morison_f_over_rho_u2_d"]) for r in ref])
    data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "dutsch1998",
                        "inline_force_re100_kc5.csv")
    dig = read_rows(data) if os.path.isfile(data) else []
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7))
    t_end = max(max(t) for t, _ in runs.values())
    n = int(round(t_end / period))
    if n >= 1:
        tt = np.concatenate([(k + rt[:-1]) * period for k in range(n)] + [[n * period]])
        ff = np.concatenate([rf[:-1]] * n + [[rf[0]]])
        top.plot(tt / period, ff, "k--", lw=1.2, label="Morison, C_d = 2.09, C_i = 1.45")
    for k, (name, (t, f)) in enumerate(runs.items()):
        t, f = np.array(t), np.array(f)
        top.plot(t / period, f, lw=0.6, color=f"C{k}", label=name)
        run_end = round(t[-1] / period) * period  # runs differ in length
        last = t >= run_end - period - 1e-9
        width = max(1, int(round(last.sum() / 40)))
        smooth = np.convolve(f, np.ones(width) / width, mode="same")
        phase = (t[last] - (run_end - period)) / period
        bottom.plot(phase, f[last], lw=0.4, color=f"C{k}", alpha=0.5)
        bottom.plot(phase, smooth[last], lw=1.5, color=f"C{k}", label=f"{name}, period {int(round(run_end / period))}")
    bottom.plot(rt, rf, "k--", lw=1.2, label="Morison, C_d = 2.09, C_i = 1.45")
    if dig:
        bottom.plot([float(r["t_over_T"]) for r in dig], [float(r["f_over_rho_u2_d"]) for r in dig],
                    "ko", ms=5, mfc="none", label="Dütsch et al. (1998), digitised")
    # The impulsive start (the cylinder set moving at U_max at t = 0) gives a spike of about
    # 15 rho U^2 D in the first steps: cut off, so that the periods stay readable.
    top.set_ylim(-4, 4)
    top.set_xlabel("t / T")
    top.set_ylabel("F / (rho U_max^2 D)")
    top.set_title("In-line oscillating cylinder, Re = 100, KC = 5")
    bottom.set_xlabel("phase t / T within the last period")
    bottom.set_ylabel("F / (rho U_max^2 D)")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "oscillating_cylinder.png"), dpi=120)


if __name__ == "__main__":
    main()
