"""Plots of `curvsph validate surge_front`. Usage: plot_surge_front.py OUT_DIR

surge_front.png: (left) the dam break's surge front Z = x/a against T = t sqrt(2g/a) for every
run, beside Martin & Moyce (1952, Fig. 3, n^2 = 2, both column sizes), Koshizuka & Oka (1996)
and Ritter's shallow-water front Z = 1 + 2T; (middle) the lag T_exp - T_sim(Z_exp) against the
experiment's Z: constant for a delayed start, growing for a slower front; (right) the height of
the water on the far wall over the column height 2a."""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(path):
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def main():
    out = sys.argv[1]
    data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "martin_moyce")
    fig, (ax, lx, bx) = plt.subplots(1, 3, figsize=(15, 4.5))
    for path in sorted(glob.glob(os.path.join(out, "runs", "*", "surge_front.csv"))):
        tag = os.path.basename(os.path.dirname(path))
        d = load(path)
        if not d:
            continue
        main_run = tag.endswith("mirror_beta") or tag.endswith("integrals")
        style = dict(lw=1.4 if main_run else 0.8, ls="-" if main_run else ":")
        ax.plot(d["T"], d["Z"], label=tag, **style)
        c = load(os.path.join(os.path.dirname(path), "surge_front_compare.csv"))
        if c:
            lx.plot(c["Z_exp"], c["lag"], "o-", ms=3, label=tag, **style)
        if max(d["far_wall_height"]) > 0:
            bx.plot(d["T"], d["far_wall_height"], label=tag, **style)
    for name, label, marker in [("front_a_2.25in.csv", "Martin & Moyce, a = 2.25 in", "ko"),
                                ("front_a_1.125in.csv", "Martin & Moyce, a = 1.125 in", "ks"),
                                ("front_koshizuka_oka_1996.csv", "Koshizuka & Oka (1996)", "k^")]:
        e = load(os.path.join(data, name))
        if e:
            ax.plot(e["T"], e["Z"], marker, ms=4, mfc="none" if "1.125" in name or "Kosh" in name
                    else "k", label=label)
    ax.plot([0, 7.5], [1, 16], "k--", lw=0.8, label="Ritter: Z = 1 + 2T")
    ax.set_xlabel("T = t sqrt(2g/a)")
    ax.set_ylabel("Z = x/a")
    ax.set_xlim(0, 10)
    ax.set_ylim(0, 17)
    ax.set_title("Surge front")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    lx.set_xlabel("Z = x/a (Martin & Moyce, a = 2.25 in)")
    lx.set_ylabel("T_exp - T_sim at that Z")
    lx.set_title("Lag of the experiment behind the simulation")
    lx.grid(alpha=0.3)
    lx.legend(fontsize=7)
    bx.set_xlabel("T = t sqrt(2g/a)")
    bx.set_ylabel("height on the far wall / 2a")
    bx.set_title("Run-up on the far wall (x = 16 a)")
    bx.grid(alpha=0.3)
    bx.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "surge_front.png"), dpi=110)


if __name__ == "__main__":
    main()
