"""Plot of `curvsph validate cad_at_rest`. Usage: plot_cad_at_rest.py OUT_DIR

pressure_error.png: for every solid (groups) and boundary method (bars) the RMS of
p - rho0 g (H - z) over the particles at least 2h below the surface at the end, over rho0 g H,
with the 2 % target; a hatched bar marks a run in which particles were put back from past a wall."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    out = sys.argv[1]
    with open(os.path.join(out, "runs.csv")) as f:
        rows = list(csv.DictReader(f))
    solids = list(dict.fromkeys(r["solid"] for r in rows))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    fig, ax = plt.subplots(figsize=(max(10.0, 1.5 * len(solids)), 4))
    w = 0.8 / max(len(methods), 1)
    for k, m in enumerate(methods):
        for i, s in enumerate(solids):
            r = [x for x in rows if x["solid"] == s and x["method"] == m]
            if not r:
                continue
            v = float(r[0]["pressure_rms_deep"])
            crossed = float(r[0]["particles_projected"] or 0) > 0
            ax.bar(i + (k - (len(methods) - 1) / 2) * w, v, w, color=f"C{k}",
                   hatch="//" if crossed else None, label=m if i == 0 else None)
    ax.axhline(0.02, color="k", ls="--", lw=1, label="2 % target")
    ax.set_xticks(range(len(solids)))
    ax.set_xticklabels(solids)
    ax.set_yscale("log")
    ax.set_ylabel("RMS (p - rho0 g (H - z)) / rho0 g H, deep")
    ax.set_title("Water at rest after the run (hatched: particles put back from past a wall)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pressure_error.png"), dpi=120)


if __name__ == "__main__":
    main()
