"""2D-2 (Re = 100) figures of a cylinder_channel_re100 run folder from its forces.csv and
probes.csv: Strouhal number, C_D,max, C_L,max and dp half a period after the lift maximum,
by the method of periodic_figures (src/curvsph/analysis/cylinder_benchmark.cpp): periods from
upward crossings of the window mean by the lift on a running mean over a twentieth of the
reference period, with a hysteresis band of +-0.5 std; in each period the raw signals are
fitted by least squares with a mean and three harmonics, and the maxima are the fits' maxima,
averaged over the periods. For a run still in progress (or one written by `curvsph run`
outside the study).
Usage: /usr/bin/python3 scripts/cylinder_re100_figures.py RUN_DIR FROM [TO] [--plot OUT.png]
(--plot: C_D and C_L, raw and on a running mean over 0.1 s, against the reference maxima)."""
import csv
import sys

import numpy as np

D, U, ST_REF = 0.1, 1.0, 0.300  # cases/cylinder_channel_re100.yaml: U = 2 U_m / 3


def columns(path):
    rows = list(csv.reader(open(path)))
    data = np.array([[float(x) for x in r] for r in rows[1:] if r])
    return {h: data[:, k] for k, h in enumerate(rows[0])}


def running_mean(t, v, width):
    out = np.empty_like(v)
    for k in range(len(t)):
        m = np.abs(t - t[k]) <= width / 2
        out[k] = v[m].mean()
    return out


def fit(t, v, t0, t1):
    m = (t >= t0) & (t <= t1)
    w = 2 * np.pi / (t1 - t0)
    basis = lambda s: np.column_stack([np.ones_like(s)] + [f(j * w * (s - t0)) for j in (1, 2, 3)
                                                            for f in (np.cos, np.sin)])
    c, *_ = np.linalg.lstsq(basis(t[m]), v[m], rcond=None)
    return lambda s: basis(np.atleast_1d(np.asarray(s, float))) @ c


def plot(out, t, cd, cl, run):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for a, v, name, ref in ((ax[0], cd, "C_D", 3.23), (ax[1], cl, "C_L", 1.00)):
        a.plot(t, v, lw=0.3, color="0.7", label="raw (every 0.01 s)")
        a.plot(t, running_mean(t, v, 0.1), lw=1.2, color="C0", label="running mean over 0.1 s")
        a.axhline(ref, ls="--", color="C3", lw=0.8, label=f"reference max {ref}")
        if name == "C_L":
            a.axhline(-ref, ls="--", color="C3", lw=0.8)
            a.set_ylim(-2.5, 2.5)
        else:
            a.set_ylim(0, 6)
        a.set_ylabel(name)
        a.legend(loc="upper left", fontsize=7)
    ax[1].set_xlabel("t (s)")
    ax[0].set_title(f"Cylinder in a channel, Re = 100, D/dx = 10 ({run})")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main():
    args = sys.argv[1:]
    out = None
    if "--plot" in args:
        k = args.index("--plot")
        out = args[k + 1]
        del args[k:k + 2]
    sys.argv = sys.argv[:1] + args
    run, t_from = sys.argv[1], float(sys.argv[2])
    f = columns(run + "/forces.csv")
    p = columns(run + "/probes.csv")
    q = 0.5 * 1.0 * U * U * D
    t = f["time"]
    t_to = float(sys.argv[3]) if len(sys.argv) > 3 else t[-1]
    cd, cl = f["cylinder.fx"] / q, f["cylinder.fy"] / q
    tp, dp = p["time"], p["front.p"] - p["back.p"]
    if out:
        plot(out, t, cd, cl, run.rstrip("/").split("/")[-1])
    scl = running_mean(t, cl, D / (ST_REF * U) / 20)
    win = (t >= t_from) & (t <= t_to)
    mean, std = scl[win].mean(), scl[win].std()
    lo, hi = mean - 0.5 * std, mean + 0.5 * std
    up, state, cand = [], 0, np.nan
    idx = np.nonzero(win)[0]
    for k in idx[1:]:
        v0, v1 = scl[k - 1], scl[k]
        if v0 < mean <= v1:
            cand = t[k - 1] + (mean - v0) / (v1 - v0) * (t[k] - t[k - 1])
        if v1 < lo:
            state, cand = -1, np.nan
        elif v1 > hi:
            if state == -1 and not np.isnan(cand):
                up.append(cand)
            state = 1
    if len(up) < 3:
        print(f"{run}: no shedding found in [{t_from}, {t_to}] s ({len(up)} crossings)")
        return
    periods = len(up) - 1
    freq = periods / (up[-1] - up[0])
    T = np.diff(up)
    cdm, clm, clmin, dph = [], [], [], []
    for a, b in zip(up[:-1], up[1:]):
        s = np.linspace(a, b, 400)
        fl, fd, fp = fit(t, cl, a, b), fit(t, cd, a, b), fit(tp, dp, a, b)
        yl = fl(s)
        clm.append(yl.max())
        clmin.append(yl.min())
        cdm.append(fd(s).max())
        dph.append(fp(s[yl.argmax()] + 0.5 * (b - a))[0])
    st = freq * D / U
    print(f"{run}: [{t_from}, {t_to:.2f}] s, {periods} periods (spread {T.std() / T.mean():.3f}), "
          f"St = {st:.4f} (0.300: {100 * (st / 0.3 - 1):+.1f} %), "
          f"C_D,max = {np.mean(cdm):.4f} (3.23: {100 * (np.mean(cdm) / 3.23 - 1):+.1f} %), "
          f"C_L,max = {np.mean(clm):.4f} (1.00: {100 * (np.mean(clm) - 1):+.1f} %), "
          f"C_L,min = {np.mean(clmin):.4f}, dp(t0 + T/2) = {np.mean(dph):.4f} (2.46-2.50); "
          f"C_D mean {cd[win].mean():.4f}, raw C_L std {cl[win].std():.3f}")


if __name__ == "__main__":
    main()
