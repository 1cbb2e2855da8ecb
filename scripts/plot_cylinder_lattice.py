"""Plots of `curvsph validate cylinder_lattice`: Fig. 9-like v_y contours (mirror as the
heat map and red contours, density-preserving as blue contours) and Fig. 10-like mean t_max
against v0 per map."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

out = sys.argv[1]
levels = [-0.25, -1 / 6, -1 / 12, 0, 1 / 12, 1 / 6, 0.25]


def field(m):
    p = os.path.join(out, f"fig9_{m}", "velocity.csv")
    if not os.path.exists(p):
        return None
    a = np.loadtxt(p, delimiter=",", skiprows=1)
    return a


def smooth_grid(a, n=101, h=0.03):
    """Kernel (Shepard) average of v_y on a grid, periodic images included."""
    g = np.linspace(-0.5, 0.5, n)
    X, Y = np.meshgrid(g, g)
    num = np.zeros_like(X)
    den = np.zeros_like(X)
    for sx in (-1, 0, 1):
        for sy in (-1, 0, 1):
            px = a[:, 0] + sx
            py = a[:, 1] + sy
            for k in range(len(px)):
                if abs(px[k]) > 0.5 + 2 * h or abs(py[k]) > 0.5 + 2 * h:
                    continue
                i0 = max(0, int((px[k] - 2 * h + 0.5) / (1.0 / (n - 1))))
                i1 = min(n, int((px[k] + 2 * h + 0.5) / (1.0 / (n - 1))) + 2)
                j0 = max(0, int((py[k] - 2 * h + 0.5) / (1.0 / (n - 1))))
                j1 = min(n, int((py[k] + 2 * h + 0.5) / (1.0 / (n - 1))) + 2)
                dx = X[j0:j1, i0:i1] - px[k]
                dy = Y[j0:j1, i0:i1] - py[k]
                q = np.sqrt(dx * dx + dy * dy) / h
                w = np.where(q < 2, (1 - q / 2) ** 4 * (2 * q + 1), 0.0)
                num[j0:j1, i0:i1] += w * a[k, 3]
                den[j0:j1, i0:i1] += w
    v = np.where(den > 1e-12, num / np.maximum(den, 1e-12), np.nan)
    v[X * X + Y * Y < 0.2 ** 2] = np.nan
    return X, Y, v


fm, fd = field("mirror"), field("density_preserving")
if fm is not None and fd is not None:
    fig, ax = plt.subplots(figsize=(6.4, 5.4))
    X, Y, vm = smooth_grid(fm)
    _, _, vd = smooth_grid(fd)
    im = ax.pcolormesh(X, Y, vm, cmap="coolwarm", vmin=-0.3, vmax=0.3, shading="auto")
    ax.contour(X, Y, vm, levels=levels, colors="red", linewidths=0.9)
    ax.contour(X, Y, vd, levels=levels, colors="blue", linewidths=0.9, linestyles="--")
    ax.add_patch(plt.Circle((0, 0), 0.2, color="0.3"))
    fig.colorbar(im, ax=ax, label="v_y (mirror)")
    ax.set_aspect("equal")
    ax.set_title("v_y: mirror (map, red) vs density-preserving (blue dashed)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig9_vy.png"), dpi=110)
    plt.close(fig)

# Fig. 9 companion: mean v_x against time (is the flow steady at the end?).
hist = {m: os.path.join(out, f"fig9_{m}", "history.csv") for m in ("mirror", "density_preserving")}
if all(os.path.exists(p) for p in hist.values()):
    fig, ax = plt.subplots(figsize=(5.8, 4.2))
    for (m, p), c in zip(hist.items(), ("tab:red", "tab:blue")):
        a = np.loadtxt(p, delimiter=",", skiprows=1, ndmin=2)
        ax.plot(a[:, 0], a[:, 1], "o-", color=c, ms=3, label=m)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("mean v_x")
    ax.set_title("Fig. 9 runs (v0 = 0.5): mean v_x")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig9_history.png"), dpi=110)
    plt.close(fig)

p = os.path.join(out, "tmax_mean.csv")
if os.path.exists(p):
    rows = list(csv.DictReader(open(p)))
    fig, ax = plt.subplots(figsize=(5.8, 4.2))
    # Mirror drawn with larger markers under the density-preserving line: equal values overlap.
    for m, c, st, ms in (("mirror", "tab:red", "o-", 8), ("density_preserving", "tab:blue", "s--", 4),
                         ("mirror_coarsest", "0.5", "^-", 5)):
        r = sorted([x for x in rows if x["map"] == m], key=lambda x: float(x["v0"]))
        if not r:
            continue
        v0 = [float(x["v0"]) for x in r]
        n = r[0]["runs"]
        ax.plot(v0, [float(x["tmax_mean"]) for x in r], st, color=c, ms=ms,
                label=f"{m}: mean of {n} runs")
        ax.plot(v0, [float(x["tmax_min"]) for x in r], "v:", color=c, ms=4, label=f"{m}: min")
    ax.text(0.02, 0.98, "mirror_coarsest: diagnostic, the mirror at its own coarsest dx",
            transform=ax.transAxes, fontsize=7, va="top")
    ax.set_xlabel("v0")
    ax.set_ylabel("t_max (s)")
    ax.set_ylim(0, 10.5)
    ax.set_title("Lattice of cylinders, low resolution (Fig. 10)")
    ax.legend(fontsize=8, loc="lower left")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig10_tmax.png"), dpi=110)
    plt.close(fig)
