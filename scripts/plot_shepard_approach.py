#!/usr/bin/python3
"""Plots of the `shepard_approach` validation study (Calderon et al. Figs. 2, 4-7).

Usage: plot_shepard_approach.py OUT_DIR
Reads OUT_DIR/h_over_dx_2/shepard_<approach>.csv and OUT_DIR/error_vs_h_over_dx.csv, writes
OUT_DIR/shepard_<approach>.png and OUT_DIR/error_vs_h_over_dx.png.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

APPROACHES = {
    "wall": "flat wall (Fig. 4)",
    "corner_side": "90° corner, along a side on the contour (Figs. 2, 5 left)",
    "corner_diagonal": "90° corner, along the diagonal (Fig. 5 right)",
    "circle_inside": "circle R = 4h, fluid inside (Fig. 6)",
    "circle_outside": "circle R = 4h, fluid outside",
}
STYLES = [
    ("reference", "quadrature reference", dict(color="tab:green", lw=2.5)),
    ("geometric", "geometric (split F)", dict(color="tab:red", lw=1.5)),
    ("monolithic", "monolithic F", dict(color="black", ls="--", lw=1.2)),
    ("monolithic_contour", "monolithic, γ = 1/2 on the contour", dict(color="0.5", ls=":", lw=1.5)),
    ("volume", "volume sum (eq. 4)", dict(color="tab:blue", ls="-.", lw=1.2)),
]


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main(out):
    for name, title in APPROACHES.items():
        d = read(os.path.join(out, "h_over_dx_2", f"shepard_{name}.csv"))
        fig, ax = plt.subplots(figsize=(6, 4.2))
        for key, label, style in STYLES:
            col = "gamma_reference" if key == "reference" else f"gamma_{key}"
            if col in d:
                ax.plot(d["distance_over_h"], d[col], label=label, **style)
        ax.set_xlabel("distance / h" + (" (to the corner apex)" if "corner" in name else ""))
        ax.set_ylabel("Shepard factor γ")
        ax.set_title(f"{title}, h/Δr = 2", fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"shepard_{name}.png"), dpi=120)
        plt.close(fig)

    e = read(os.path.join(out, "error_vs_h_over_dx.csv"))
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for ax, approach in zip(axes, ["corner_side", "circle"]):
        for key, label, style in STYLES[1:]:
            col = f"gamma_max_abs_error_{approach}_{key}"
            ax.semilogy(e["h_over_dx"], e[col], marker="o", label=label, **style)
        ax.axhline(0.021, color="tab:orange", lw=0.8, label="paper's Fig. 2 foil error 0.021")
        ax.axhline(0.005, color="tab:red", lw=0.6, ls="--", label="target 0.005 (geometric)")
        ax.set_xlabel("h / Δr")
        ax.set_ylabel("max |γ − γ_ref|")
        ax.set_title(f"{approach} (Fig. 7)", fontsize=10)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error_vs_h_over_dx.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1])
