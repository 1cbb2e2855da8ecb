"""First-impact P1 maximum of the 3-D dam break, raw and after a Savitzky-Golay filter (issue 5).

Usage: dam_break_filtered_peak.py EXPERIMENT.dat LABEL=RUN_DIR [LABEL=RUN_DIR ...]

Calderon et al. (§3.2, after Fig. 15) smooth their SPH pressure records with a Savitzky-Golay
filter before comparing them with the experiment, without giving the window. This prints, for
the experiment and for each run's probes.csv (1 kHz samples), the P1 maximum over the first
impact (t <= 0.435 s for the runs, t <= 1.5 s for the experiment) raw and filtered with a
quadratic Savitzky-Golay filter of 11, 21 and 41 samples (11, 21, 41 ms), and its ratio to the
experimental peak. A diagnostic: the study's figure stays the raw one.
"""
import csv
import sys

import numpy as np
from scipy.signal import savgol_filter

WINDOWS = (11, 21, 41)


def filtered_maxima(p, mask):
    p = np.nan_to_num(p)  # no fluid within the probe's support before the impact
    return [p[mask].max()] + [savgol_filter(p, w, 2)[mask].max() for w in WINDOWS]


def main():
    exp = np.loadtxt(sys.argv[1], skiprows=1)
    exp_peak = exp[exp[:, 0] <= 1.5, 1].max()
    header = "| record | raw | " + " | ".join(f"SG {w} ms" for w in WINDOWS) + " |"
    print(header)
    print("|---" * (len(WINDOWS) + 2) + "|")
    maxima = filtered_maxima(exp[:, 1], exp[:, 0] <= 1.5)
    print("| experiment | " + " | ".join(f"{m:.0f} Pa" for m in maxima) + " |")
    for arg in sys.argv[2:]:
        label, run = arg.split("=", 1)
        with open(f"{run}/probes.csv") as f:
            rows = list(csv.reader(f))
        col = rows[0].index("P1.p_wall")
        t = np.array([float(r[0]) for r in rows[1:]])
        p = np.array([float(r[col]) for r in rows[1:]])
        maxima = filtered_maxima(p, t <= 0.435)
        print(f"| {label} | " + " | ".join(f"{m:.0f} Pa ({m / exp_peak:.2f})" for m in maxima) + " |")


if __name__ == "__main__":
    main()
