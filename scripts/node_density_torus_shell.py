#!/usr/bin/env python3
"""Why the density-preserving ghosts of the node_density torus miss 0.02 (issue #4): the
ghost-shell truncation model, checked against the measured node density.

With one ghost per fluid particle (Vela Vela §7) the density-preserving map sends the whole
tube (depth d <= a) onto a ghost shell of thickness z(theta), the root of G(z) = -G(-a)
(DESIGN.md §4; torus: k1 = 1/a, k2 = cos(theta)/(R + a cos(theta))). A ghost at depth z' whose
kernel support reaches past the shell (z' + 2h > z(theta)) misses the ghosts beyond it: its n
falls by the fraction F(s) of the kernel beyond a plane at distance s = z(theta) - z'
(Wendland C2, 3-D, computed here by quadrature; the shell's curvature is neglected).

    /usr/bin/python3 scripts/node_density_torus_shell.py POINTS_CSV H [NOISE_STD [PNG]]
    /usr/bin/python3 scripts/node_density_torus_shell.py --predict NOISE_STD DX [DX ...]

The first form bins the measured |n/n_ref - 1| of the density_preserving (and mirror) ghosts
within 2h (node_density_points.csv with positions, h = 1.5 dx) by poloidal angle and by depth
and prints the model next to it (and plots both into PNG when given). The second predicts the figure ghost_node_density_dev for
other dx (h = 1.5 dx) from the model plus the relaxation's node-density noise (a Gaussian of
the given standard deviation, the interior spread of the run).
"""
import csv
import math
import sys

R, A = 3.0, 1.0


def g_vol(z, k1, k2):  # DESIGN.md §4: G(z) = z + (k1 + k2) z^2 / 2 + k1 k2 z^3 / 3
    return z + (k1 + k2) * z * z / 2 + k1 * k2 * z**3 / 3


def kappa2(th):
    return math.cos(th) / (R + A * math.cos(th))


def shell(th):
    """Ghost-shell thickness z(theta): G(z) = -G(-a), bisection (G increasing for z > 0)."""
    k1, k2 = 1 / A, kappa2(th)
    target, lo, hi = -g_vol(-A, k1, k2), 0.0, 4.0
    for _ in range(100):
        m = 0.5 * (lo + hi)
        lo, hi = (m, hi) if g_vol(m, k1, k2) < target else (lo, m)
    return lo


def wendland3(q):  # Wendland C2, 3-D, h = 1 (DESIGN.md §4)
    return 21 / (16 * math.pi) * (1 - q / 2) ** 4 * (2 * q + 1) if q < 2 else 0.0


def _plane_mass(x, n=200):
    """Kernel integrated over the plane at distance x from its centre (h = 1)."""
    rmax = math.sqrt(max(0.0, 4 - x * x))
    s = 0.0
    for i in range(n):  # midpoint rule in rho
        rho = (i + 0.5) * rmax / n
        s += wendland3(math.hypot(x, rho)) * rho
    return 2 * math.pi * s * rmax / n


_TAIL = []


def tail(s_over_h):
    """F(s): kernel mass beyond a plane at distance s (in units of h); F(0) = 1/2, F(2) = 0."""
    if not _TAIL:
        n = 400
        xs = [2 * (i + 0.5) / n for i in range(n)]
        ms = [_plane_mass(x) * 2 / n for x in xs]
        acc = 0.0
        for i in reversed(range(n)):
            acc += ms[i]
            _TAIL.append((2 * i / n, acc))
        _TAIL.reverse()
    if s_over_h >= 2:
        return 0.0
    if s_over_h < 0:
        return 1.0 - tail(-s_over_h)
    i = min(len(_TAIL) - 2, int(s_over_h / 2 * (len(_TAIL))))
    (x0, f0), (x1, f1) = _TAIL[i], _TAIL[i + 1]
    return f0 + (f1 - f0) * (s_over_h - x0) / (x1 - x0)


def means(v):
    """Means of the three columns of (|n/n_ref - 1|, n/n_ref - 1, model - 1) records."""
    return tuple(sum(col) / len(v) for col in zip(*v))


def mean_abs_gauss(b, sd, n=41):
    """E|b + N(0, sd)| by Gauss-Hermite-like midpoint sampling on +-4 sd."""
    if sd <= 0:
        return abs(b)
    tot = wsum = 0.0
    for i in range(n):
        x = -4 + 8 * (i + 0.5) / n
        w = math.exp(-x * x / 2)
        tot += w * abs(b + sd * x)
        wsum += w
    return tot / wsum


def predict(dx, sd, nth=90, nz=40):
    """Model figure at dx: mean over ghosts within 2h (weight: wall area x ghost density)."""
    h = 1.5 * dx
    num = den = 0.0
    for i in range(nth):
        th = (i + 0.5) * math.pi / nth  # symmetric in +-theta
        zt = shell(th)
        area = R + A * math.cos(th)
        for j in range(nz):
            z = (j + 0.5) * 2 * h / nz
            if z >= zt:
                continue  # no ghosts beyond the shell
            w = area * (1 + z / A) * (1 + kappa2(th) * z)  # J(z): ghost count per depth
            num += w * mean_abs_gauss(-tail((zt - z) / h), sd)
            den += w
    return num / den


def measured(path, h, sd, png=None):
    plot = {}
    rows = [r for r in csv.DictReader(open(path))
            if r["kind"] == "ghost" and r.get("band", "all") == "all"]
    for mp in ["mirror", "density_preserving"]:
        by_th, by_z, allv = {}, {}, []
        for r in rows:
            if r["map"] != mp:
                continue
            z = -float(r["distance"])
            if z >= 2 * h:
                continue
            x, y, zz = float(r["x0"]), float(r["x1"]), float(r["x2"])
            th = math.atan2(zz, math.hypot(x, y) - R)  # 0: outer equator, pi: the hole side
            nrel = float(r["n_rel"])
            model = 1 - tail((shell(th) - z) / h) if mp == "density_preserving" else float("nan")
            rec = (abs(nrel - 1), nrel - 1, model - 1)
            by_th.setdefault(min(5, int(abs(th) / math.pi * 6)), []).append(rec)
            by_z.setdefault(min(5, int(z / (2 * h) * 6)), []).append(rec)
            allv.append(rec)
        print(f"{mp}: dev = {sum(a for a, _, _ in allv) / len(allv):.4f} over {len(allv)} sampled ghosts")
        print("  |theta| (deg)  shell z  dev     mean(n/n_ref-1)  model mean  count")
        for k in sorted(by_th):
            dev, mean, model = means(by_th[k])
            print(f"  {30 * k:3d}-{30 * k + 30:3d}      {shell(math.radians(30 * k + 15)):.3f}   "
                  f"{dev:.4f}  {mean:+.4f}          {model:+.4f}     {len(by_th[k])}")
        print("  depth/2h       dev     mean(n/n_ref-1)  model mean  count")
        for k in sorted(by_z):
            dev, mean, model = means(by_z[k])
            print(f"  {k / 6:.2f}-{(k + 1) / 6:.2f}      {dev:.4f}  {mean:+.4f}          "
                  f"{model:+.4f}     {len(by_z[k])}")
        if mp == "density_preserving":
            plot = {"th": by_th, "z": by_z}
            full = [a for a, _, c in allv if c > -1e-12]
            print(f"  ghosts with complete support (model F = 0): dev {sum(full) / max(1, len(full)):.4f}"
                  f" over {len(full)}")
            print(f"  model dev at this h (noise sd {sd}): {predict(h / 1.5, sd):.4f}")
    if png and plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(10, 4))
        for a, key, xs, label in ((ax[0], "th", lambda k: 30 * k + 15, "|poloidal angle| (deg): 0 outer equator, 180 hole side"),
                                  (ax[1], "z", lambda k: (k + 0.5) / 6, "ghost depth / 2h")):
            ks = sorted(plot[key])
            v = plot[key]
            a.plot([xs(k) for k in ks], [sum(r[1] for r in v[k]) / len(v[k]) for k in ks], "o-",
                   label="measured mean n/n_ref - 1")
            a.plot([xs(k) for k in ks], [sum(r[2] for r in v[k]) / len(v[k]) for k in ks], "s--",
                   label="shell-truncation model -F")
            a.plot([xs(k) for k in ks], [sum(r[0] for r in v[k]) / len(v[k]) for k in ks], "^:",
                   label="measured mean |n/n_ref - 1|")
            a.axhline(0.02, color="grey", lw=0.5)
            a.axhline(-0.02, color="grey", lw=0.5)
            a.set_xlabel(label)
            a.grid(alpha=0.3)
        ax[0].legend(fontsize=8)
        ax[0].set_title(f"torus, density_preserving ghosts within 2h (h = {h:g})", fontsize=9)
        fig.tight_layout()
        fig.savefig(png, dpi=110)


if __name__ == "__main__":
    if sys.argv[1] == "--predict":
        sd = float(sys.argv[2])
        print("dx      h       4h/z_min  model ghost_node_density_dev")
        for dx in map(float, sys.argv[3:]):
            print(f"{dx:.4f}  {1.5 * dx:.4f}  {6 * dx / shell(0.0):.2f}      {predict(dx, sd):.4f}")
    else:
        measured(sys.argv[1], float(sys.argv[2]), float(sys.argv[3]) if len(sys.argv) > 3 else 0.0,
                 sys.argv[4] if len(sys.argv) > 4 else None)
