"""Plots of `curvsph validate taylor_green`: error vs dx with the fitted order, and the
kinetic energy history of each resolution against the analytic decay."""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "taylor_green.csv"))))
dx = np.array([float(r["dx"]) for r in rows])
l2 = np.array([float(r["l2_velocity_error"]) for r in rows])
dr = np.array([float(r["decay_rate_rel_error"]) for r in rows])

fig, ax = plt.subplots(figsize=(5.5, 4.2))
slope, icpt = np.polyfit(np.log(dx), np.log(l2), 1)
ax.loglog(dx, l2, "o-", label=f"velocity L2 error (fitted order {slope:.2f})")
ax.loglog(dx, np.maximum(dr, 1e-6), "s--", label="decay-rate relative error")
if rows and "tvf_l2_velocity_error" in rows[0]:
    tl2 = np.array([float(r["tvf_l2_velocity_error"]) for r in rows])
    tdr = np.array([float(r["tvf_decay_rate_rel_error"]) for r in rows])
    ax.loglog(dx, tl2, "o-", color="C2", label="transport velocity: velocity L2 error")
    ax.loglog(dx, np.maximum(tdr, 1e-6), "s--", color="C3",
              label="transport velocity: decay-rate error")
ax.axhline(0.05, color="gray", lw=0.8, ls=":", label="target 0.05")
ax.set_xlabel("dx")
ax.set_ylabel("error")
ax.set_title("Taylor–Green vortex, Re = 100, t = end")
ax.legend(fontsize=8)
ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(out, "error_vs_dx.png"), dpi=120)

fig, ax = plt.subplots(figsize=(5.5, 4.2))
for path in sorted(glob.glob(os.path.join(out, "dx_*", "taylor_green_energy.csv"))):
    d = np.genfromtxt(path, delimiter=",", names=True)
    tag = os.path.basename(os.path.dirname(path))
    label = tag.replace("_tvf", " (transport velocity)").replace("_", " = ", 1)
    ax.semilogy(d["time"], d["kinetic_energy"] / d["kinetic_energy"][0],
                ls=":" if tag.endswith("_tvf") else "-", label=label)
    exact = d
ax.semilogy(exact["time"], exact["kinetic_energy_exact"] / exact["kinetic_energy_exact"][0], "k--",
            label="analytic exp(-16 pi^2 nu t)")
ax.set_xlabel("t")
ax.set_ylabel("E_k / E_k(0)")
ax.legend(fontsize=8)
ax.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(out, "kinetic_energy.png"), dpi=120)
