"""Plots of `curvsph validate free_surface`. Usage: plot_free_surface.py OUT_DIR

surge_front.png: the dam break's surge front Z = x/a against T = t sqrt(2g/a) for every boundary
method, beside Martin & Moyce (1952, Fig. 3, n^2 = 2, a = 2.25 in); and the height of the water
on the far wall over the column height 2a."""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def main():
    out = sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    exp = load(os.path.join(here, "..", "..", "shared", "data", "martin_moyce", "front_a_2.25in.csv"))
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4))
    for path in sorted(glob.glob(os.path.join(out, "runs", "dam_break_2d_*", "surge_front.csv"))):
        d = load(path)
        if not d:
            continue
        label = os.path.basename(os.path.dirname(path))[len("dam_break_2d_"):].replace("_", " ", 1)
        ax.plot(d["T"], d["Z"], "-", lw=1.2, label=label)
        bx.plot(d["T"], d["far_wall_height"], "-", lw=1.2, label=label)
    if exp:
        ax.plot(exp["T"], exp["Z"], "ko", ms=4, label="Martin & Moyce (1952)")
    ax.set_xlabel("T = t sqrt(2g/a)")
    ax.set_ylabel("Z = x/a")
    ax.set_ylim(0, 17)
    ax.set_title("Surge front")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    bx.set_xlabel("T = t sqrt(2g/a)")
    bx.set_ylabel("height on the far wall / 2a")
    bx.set_title("Run-up on the far wall (x = 16 a)")
    bx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "surge_front.png"), dpi=120)


if __name__ == "__main__":
    main()
