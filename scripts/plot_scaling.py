"""Plots of `curvsph validate scaling`: measured particle-steps per second against ranks
(strong and weak), and the model's efficiency extrapolated to 1024 ranks."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1]
meas = list(csv.DictReader(open(os.path.join(out, "scaling_measured.csv"))))
model = list(csv.DictReader(open(os.path.join(out, "scaling_model.csv"))))

fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.2))
for kind, marker in (("strong", "o-"), ("weak", "s--")):
    rows = [r for r in meas if r["kind"] == kind]
    if not rows:
        continue
    ranks = [int(r["ranks"]) for r in rows]
    pss = [float(r["particle_steps_per_second"]) for r in rows]
    a1.plot(ranks, pss, marker, label=f"{kind} (measured)")
    if kind == "strong":
        cores = os.cpu_count() or 1
        a1.plot(ranks, [pss[0] * min(r, cores) for r in ranks], ":", color="gray",
                label=f"ideal on {cores} cores (strong)")
a1.set_xlabel("ranks (1 OpenMP thread each; 2 cores, oversubscribed beyond 2)")
a1.set_ylabel("particle-steps / s")
a1.set_xticks([1, 2, 4])
a1.set_title("3-D periodic box")
a1.grid(True, alpha=0.3)
a1.legend(fontsize=8)

for n, marker in (("200000", "o-"), ("1000000", "s-")):
    rows = [r for r in model if r["particles_per_rank"] == n]
    ranks = [int(r["ranks"]) for r in rows]
    a2.semilogx(ranks, [float(r["efficiency"]) for r in rows], marker,
                label=f"{int(n):.0e} per rank, as coded")
    a2.semilogx(ranks, [float(r["efficiency_neighbour_only"]) for r in rows], marker.replace("-", "--"),
                label=f"{int(n):.0e} per rank, neighbour-only sizes")
a2.axhline(0.8, color="gray", lw=0.8, ls=":")
a2.set_xlabel("ranks")
a2.set_ylabel("weak-scaling efficiency (model)")
a2.set_ylim(0, 1.05)
a2.set_title("model from measured halo volumes and messages")
a2.grid(True, which="both", alpha=0.3)
a2.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(out, "scaling.png"), dpi=120)
