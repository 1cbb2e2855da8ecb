"""Where the noise on the cylinder benchmark's force and pressure difference lies in frequency.
Usage: cylinder_benchmark_noise.py RUN_DIR FROM TO [D U_MEAN]

Reads RUN_DIR/forces.csv (cylinder.fx) and RUN_DIR/probes.csv (front.p, back.p) of a run of
cases/cylinder_channel_re20.yaml and prints, for C_D and dp over [FROM, TO] s, the share of the
variance (periodogram of the mean-removed samples) below 1, 2, 5, 10, 20 and 50 Hz, and the
correlation time (first lag where the autocorrelation falls below 1/e). It tells which remedy
the noise calls for: the streamwise acoustic mode of the channel that a velocity inlet and a
pressure outlet reflect has the frequency c0 / (4 L) (0.34 Hz for c0 = 3, L = 2.2), the
transverse modes between the channel walls c0 / (2 H) and its harmonics (3.7, 7.3, 11 Hz ...)."""
import csv
import sys

import numpy as np


def main():
    run, a, b = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    D = float(sys.argv[4]) if len(sys.argv) > 4 else 0.1
    U = float(sys.argv[5]) if len(sys.argv) > 5 else 0.2
    q = 0.5 * U * U * D
    f = list(csv.DictReader(open(f"{run}/forces.csv")))
    p = list(csv.DictReader(open(f"{run}/probes.csv")))
    t = np.array([float(r["time"]) for r in f])
    cd = np.array([float(r["cylinder.fx"]) for r in f]) / q
    tp = np.array([float(r["time"]) for r in p])
    dp = np.array([float(r["front.p"]) - float(r["back.p"]) for r in p])
    for name, tt, v in (("C_D", t, cd), ("dp", tp, dp)):
        m = (tt >= a) & (tt <= b)
        x = v[m] - v[m].mean()
        dt = tt[1] - tt[0]
        power = np.abs(np.fft.rfft(x)) ** 2
        freq = np.fft.rfftfreq(len(x), dt)
        total = power[1:].sum()
        shares = " ".join(f"<{c:g} Hz: {power[1:][freq[1:] < c].sum() / total:.3f}"
                          for c in (1, 2, 5, 10, 20, 50))
        ac = np.correlate(x, x, "full")[len(x) - 1:]
        ac /= ac[0]
        lag = int(np.argmax(ac < np.exp(-1))) * dt
        print(f"{name}: mean {v[m].mean():.4f} std {v[m].std():.4f} samples {m.sum()} "
              f"(every {dt:g} s); variance share {shares}; correlation time {lag:.4f} s")


if __name__ == "__main__":
    main()
