"""Plots of `curvsph validate node_density` (Vela Vela Figs. 6-8): node density n/n_ref of
fluid particles and ghosts against the signed distance to the wall (negative behind it),
mirror and density-preserving maps, one PNG per shape. Points and solid lines: the analysis
band (every fluid particle mirrored, as in the paper); dashed lines: the solver's band (only
fluid within 2h mirrored), when the CSV has it."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1]
colors = {"mirror": "tab:red", "density_preserving": "tab:blue", "mirror_beta": "tab:green"}
for shape in ("cylinder", "sphere", "torus"):
    pts = os.path.join(out, shape, "node_density_points.csv")
    binned = os.path.join(out, shape, "node_density_binned.csv")
    if not os.path.exists(pts):
        continue
    # Files written before the band column existed hold the analysis band only.
    rows = [r for r in csv.DictReader(open(pts)) if r.get("band", "all") == "all"]
    brows_all = list(csv.DictReader(open(binned)))
    brows = [r for r in brows_all if r.get("band", "all") == "all"]
    sbrows = [r for r in brows_all if r.get("band") == "solver"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, zoom in zip(axes, (False, True)):
        for m in ("mirror", "density_preserving"):
            for kind, mk in (("fluid", "."), ("ghost", "x")):
                sel = [r for r in rows if r["map"] == m and r["kind"] == kind]
                if kind == "fluid" and m != "density_preserving":
                    continue  # fluid n differs only near the wall: show it once per map below
                ax.scatter([float(r["distance"]) for r in sel], [float(r["n_rel"]) for r in sel],
                           s=2, marker=mk, color=colors[m] if kind == "ghost" else "0.6",
                           alpha=0.35, label=f"{kind} ({m})" if kind == "ghost" else "fluid")
            b = [r for r in brows if r["map"] == m]
            b.sort(key=lambda r: float(r["distance"]))
            ax.plot([float(r["distance"]) for r in b], [float(r["mean"]) for r in b],
                    color=colors[m], lw=1.2, label=f"binned mean ({m}, every particle mirrored)")
            sb = [r for r in sbrows if r["map"] == m]
            sb.sort(key=lambda r: float(r["distance"]))
            if sb:
                ax.plot([float(r["distance"]) for r in sb], [float(r["mean"]) for r in sb],
                        color=colors[m], lw=1.0, ls="--",
                        label=f"binned mean ({m}, solver band: fluid within 2h mirrored)")
        ax.axvline(0, color="k", lw=0.8)
        ax.axhline(1, color="k", lw=0.6, ls=":")
        ax.set_xlabel("signed distance to the wall (< 0: behind it, ghosts)")
        ax.set_ylabel("n / n_ref")
        if zoom:
            ax.set_xlim(-0.35, 0.35)
            ax.set_ylim(0.8, 1.2)
            ax.set_title(f"{shape}: near the wall")
        else:
            ax.set_title(f"{shape}: node density, mirror vs density-preserving")
            ax.legend(fontsize=7, markerscale=4)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"node_density_{shape}.png"), dpi=110)
    plt.close(fig)
