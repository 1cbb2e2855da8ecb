"""Plots of `curvsph validate couette` (Barker & Neethling Figs. 1-4).

Usage: plot_couette.py OUT_DIR PLOT_DX_MM REST_DX_MM [MU_CONTROL]
Reads OUT_DIR/couette.csv and the per-run CSVs under OUT_DIR/runs/.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

MAPS = ["mirror", "mirror_beta", "density_preserving"]
STYLE = {"mirror": ("tab:red", ":"), "mirror_beta": ("tab:blue", "-"),
         "density_preserving": ("tab:green", "--")}


def load(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]} if rows else {}


def plot_analytic(ax, d):
    """The analytic v_theta(r) (Barker eq. 24) at the particles of profile table d."""
    o = np.argsort(d["r"])
    ax.plot(d["r"][o] * 100, d["v_theta_exact"][o], "k-", lw=1, label="analytic")


def density_plot(out, what, dx, fname, title):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    for ax, m in zip(axes, ["mirror", "mirror_beta"]):
        p = os.path.join(out, "runs", f"{what}_{m}_dx{dx}mm", f"couette_density_{fname}.csv")
        if not os.path.exists(p):
            continue
        d = load(p)
        ax.plot(d["r"] * 100, d["rho_over_rho0"], ".", ms=3, color=STYLE[m][0])
        ax.axhline(1.0, color="k", lw=0.8)
        ax.set_xlabel("r (cm)")
        ax.set_title(f"{m}")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel(r"$\rho/\rho_0$")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(os.path.join(out, f"density_{fname}.png"), dpi=120)
    plt.close(fig)


def main():
    out, dx, rest_dx = sys.argv[1], sys.argv[2], sys.argv[3]
    mu_control = sys.argv[4] if len(sys.argv) > 4 else None
    density_plot(out, "t0", dx, "t0", f"Hydrostatic density at t = 0, dx = {dx} mm (Barker Fig. 1)")
    density_plot(out, "hydro", dx, "end",
                 f"Hydrostatic density at the end of the run, dx = {dx} mm (Barker Fig. 2)")

    fig, ax = plt.subplots(figsize=(6, 4))
    for m in MAPS:
        p = os.path.join(out, "runs", f"rot_{m}_dx{dx}mm", "couette_error.csv")
        if os.path.exists(p):
            d = load(p)
            ax.plot(d["time"], d["velocity_l2_error"], color=STYLE[m][0], ls=STYLE[m][1], label=m)
    ax.set_xlabel("t (s)")
    ax.set_ylabel(r"$\varepsilon / \omega R_i$")
    ax.set_title(f"Error vs time from the analytic profile, dx = {dx} mm")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error_vs_time.png"), dpi=120)
    plt.close(fig)

    # C and E: from rest, Barker's mu (solid) and the control mu (thin).
    runs = [("rest", "1e-3 Pa s", 1.6)]
    if mu_control:
        runs.append((f"rest_mu{mu_control}", f"{mu_control} Pa s", 0.8))
        wide = f"rest_mu{mu_control}_h2_mirror_beta_dx{rest_dx}mm"
        if os.path.isdir(os.path.join(out, "runs", wide)):
            runs.append((f"rest_mu{mu_control}_h2", f"{mu_control} Pa s, h = 2 dx", 0.5))
    fig, ax = plt.subplots(figsize=(6, 4))
    for what, mu, lw in runs:
        for m in MAPS:
            p = os.path.join(out, "runs", f"{what}_{m}_dx{rest_dx}mm", "couette_error.csv")
            if os.path.exists(p):
                d = load(p)
                ax.semilogy(d["time"], d["velocity_l2_error"], color=STYLE[m][0], ls=STYLE[m][1],
                            lw=lw, label=f"{m}, mu = {mu}")
    ax.set_xlabel("t (s)")
    ax.set_ylabel(r"$\varepsilon / \omega R_i$")
    ax.set_title(f"Error vs time from rest, dx = {rest_dx} mm (Barker Fig. 3b)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error_vs_time_from_rest.png"), dpi=120)
    plt.close(fig)

    # The steady mean profiles from rest: particles binned in radius (8 bins across the gap).
    fig, axes = plt.subplots(1, len(runs), figsize=(5 * len(runs), 4), squeeze=False)
    for ax, (what, mu, _) in zip(axes[0], runs):
        exact = None
        for m in MAPS:
            run = os.path.join(out, "runs", f"{what}_{m}_dx{rest_dx}mm")
            p = os.path.join(run, "couette_profile.csv")
            if not os.path.exists(p):
                continue
            if os.path.exists(os.path.join(run, "metrics_unstable.json")):
                ax.plot([], [], "o", color=STYLE[m][0], ls=STYLE[m][1], label=f"{m}: unstable")
                continue
            d = load(p)
            edges = np.linspace(d["r"].min(), d["r"].max() + 1e-12, 9)
            k = np.digitize(d["r"], edges) - 1
            rb = [d["r"][k == b].mean() for b in range(8) if np.any(k == b)]
            vb = [d["v_theta"][k == b].mean() for b in range(8) if np.any(k == b)]
            ax.plot(np.array(rb) * 100, vb, "o", color=STYLE[m][0], ls=STYLE[m][1], label=m)
            exact = d
        if exact is not None:
            plot_analytic(ax, exact)
        ax.set_xlabel("r (cm)")
        ax.set_ylabel(r"mean $v_\theta$ (m/s)")
        ax.set_title(f"From rest, mu = {mu}, at the end", fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"Steady azimuthal velocity from rest, dx = {rest_dx} mm")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profile_from_rest.png"), dpi=120)
    plt.close(fig)

    with open(os.path.join(out, "couette.csv")) as f:
        rows = list(csv.DictReader(f))
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for m in MAPS:
        rs = [r for r in rows if r["map"] == m]
        x = [float(r["dx"]) * 1e3 for r in rs]
        axes[0].loglog(x, [float(r["velocity_l2_error"]) for r in rs], "o", color=STYLE[m][0],
                       ls=STYLE[m][1], label=m)
        axes[1].loglog(x, [float(r["density_error_t0"]) for r in rs], "o", color=STYLE[m][0],
                       ls=STYLE[m][1], label=m)
    axes[0].set_ylabel(r"$\varepsilon / \omega R_i$ at the end")
    axes[0].set_title("Velocity error vs dx (Barker Fig. 4)")
    axes[1].set_ylabel(r"max $|\rho/\rho_0 - 1|$ at t = 0 (hydrostatic)")
    axes[1].set_title("Density error at t = 0 vs dx")
    for ax in axes:
        ax.set_xlabel("dx (mm)")
        ax.grid(alpha=0.3, which="both")
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error_vs_dx.png"), dpi=120)
    plt.close(fig)

    # The split of the error of B into the mean-profile error and the particle scatter.
    fig, ax = plt.subplots(figsize=(6, 4))
    for m in MAPS:
        p = os.path.join(out, "runs", f"rot_{m}_dx{dx}mm", "couette_error.csv")
        if os.path.exists(p):
            d = load(p)
            if "velocity_profile_error" not in d:
                continue
            c = STYLE[m][0]
            ax.plot(d["time"], d["velocity_l2_error"], color=c, ls="-", label=f"{m} total")
            ax.plot(d["time"], d["velocity_scatter_error"], color=c, ls="--",
                    label=f"{m} scatter")
            ax.plot(d["time"], d["velocity_profile_error"], color=c, ls=":",
                    label=f"{m} mean profile")
    ax.set_xlabel("t (s)")
    ax.set_ylabel(r"$\varepsilon / \omega R_i$")
    ax.set_title(f"Error split from the analytic profile, dx = {dx} mm")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error_split.png"), dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4))
    exact = None
    for m in MAPS:
        p = os.path.join(out, "runs", f"rot_{m}_dx{dx}mm", "couette_profile.csv")
        if os.path.exists(p):
            d = load(p)
            ax.plot(d["r"] * 100, d["v_theta"], ".", ms=2, color=STYLE[m][0], label=m)
            exact = d
    if exact is not None:
        plot_analytic(ax, exact)
    ax.set_xlabel("r (cm)")
    ax.set_ylabel(r"$v_\theta$ (m/s)")
    ax.set_title(f"Velocity profile at the end, dx = {dx} mm (Barker Fig. 3a)")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profile.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
