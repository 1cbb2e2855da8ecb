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



def finish(fig, ax, name, xlabel, ylabel, title, **legend):
    """Labels, legend and grid of a line plot; writes OUT/name and closes the figure."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(**legend)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)

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
    # How different are the two maps' fields? RMS of the difference over the grid (fluid only),
    # relative to the largest |v_y| of the mirror field.
    ok = np.isfinite(vm) & np.isfinite(vd)
    rms = np.sqrt(np.mean((vm[ok] - vd[ok]) ** 2))
    with open(os.path.join(out, "fig9_compare.md"), "w") as f:
        f.write(f"RMS of v_y(mirror) - v_y(density_preserving) on the grid: {rms:.4f} "
                f"({rms / np.abs(vm[ok]).max():.3f} of max |v_y| = {np.abs(vm[ok]).max():.3f}).\n")

# Fig. 9 companion: particle number density against the distance from the obstacle's wall at
# the end, normalised by the mean N / (1 - pi r^2): does a map leave a depleted layer (a
# stand-off gap) next to the wall? Also written as radial_density.csv and radial_density.md
# (the fill of the first layer, 0 < r - R < dx, which the study's README quotes).
R = 0.2
if fm is not None and fd is not None:
    fig, ax = plt.subplots(figsize=(5.8, 4.2))
    rows_md = []
    edges = np.arange(0.0, 5.0 + 1e-12, 0.25)  # in units of each run's dx
    prof = {}
    for m, a, c in (("mirror", fm, "tab:red"), ("density_preserving", fd, "tab:blue")):
        dx = np.sqrt((1 - np.pi * R * R) / len(a))
        rr = (np.hypot(a[:, 0], a[:, 1]) - R) / dx
        nbar = len(a) / (1 - np.pi * R * R)
        cnt, _ = np.histogram(rr, bins=edges)
        ring = np.pi * ((R + dx * edges[1:]) ** 2 - (R + dx * edges[:-1]) ** 2)
        prof[m] = cnt / (ring * nbar)
        ax.step(edges[:-1], prof[m], where="post", color=c, label=m)
        first = np.count_nonzero((rr > 0) & (rr < 1)) / (np.pi * ((R + dx) ** 2 - R * R) * nbar)
        near = rr[rr > 0].min()
        rows_md.append(f"| {m} | {len(a)} | {dx:.5f} | {first:.3f} | {near:.3f} |")
    with open(os.path.join(out, "radial_density.csv"), "w") as f:
        f.write("r_minus_R_over_dx_lo,r_minus_R_over_dx_hi,n_over_nbar_mirror,"
                "n_over_nbar_density_preserving\n")
        for k in range(len(edges) - 1):
            f.write(f"{edges[k]:.2f},{edges[k + 1]:.2f},{prof['mirror'][k]:.4f},"
                    f"{prof['density_preserving'][k]:.4f}\n")
    with open(os.path.join(out, "radial_density.md"), "w") as f:
        f.write("| map | particles | dx = sqrt(area / N) | fill of 0 < r - R < dx (n / n_mean) "
                "| closest particle (r - R) / dx |\n|---|---|---|---|---|\n")
        f.write("\n".join(rows_md) + "\n")
    ax.axhline(1.0, color="0.5", lw=0.8)
    finish(fig, ax, "fig9_radial_density.png", "(r - R) / dx (distance from the obstacle's wall)",
           "n / n_mean", "Fig. 9 runs at the end: particle density next to the obstacle")

# Fig. 9 companion: mean v_x against time (is the flow steady at the end?).
hist = {m: os.path.join(out, f"fig9_{m}", "history.csv") for m in ("mirror", "density_preserving")}
if all(os.path.exists(p) for p in hist.values()):
    fig, ax = plt.subplots(figsize=(5.8, 4.2))
    for (m, p), c in zip(hist.items(), ("tab:red", "tab:blue")):
        a = np.loadtxt(p, delimiter=",", skiprows=1, ndmin=2)
        ax.plot(a[:, 0], a[:, 1], "o-", color=c, ms=3, label=m)
    finish(fig, ax, "fig9_history.png", "t (s)", "mean v_x", "Fig. 9 runs (v0 = 0.5): mean v_x")

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
    ax.text(0.02, 0.5, "mirror_coarsest: diagnostic, the mirror at its own coarsest dx",
            transform=ax.transAxes, fontsize=7, va="top")
    ax.set_ylim(0, 10.5)
    finish(fig, ax, "fig10_tmax.png", "v0", "t_max (s)",
           "Lattice of cylinders, low resolution (Fig. 10)", fontsize=8, loc="lower left")
