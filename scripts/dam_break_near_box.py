"""Pressure near the box of the 3-D dam break, from a run's particle snapshots (issue 5).

Usage:
  dam_break_near_box.py RUN_DIR                  per snapshot: count, mean and spread of p in
                                                 front of the box face and upstream
  dam_break_near_box.py RUN_DIR --track ID       one particle: distance to the face, velocity,
                                                 pressure, density, density rate per snapshot

RUN_DIR holds particles_*.vtp and series.pvd (a `curvsph run` with output.vtk on, e.g. a
--restart at 0.40 s with output.every = 0.001). Findings: docs/validation/dam_break_3d/
findings.md, commit afec46d. Box face toward the water at x = 0.8245 m, box y in [0.295, 0.698].
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp import read_vtp  # noqa: E402

FACE_X = 0.8245
BOX_Y_MID = 0.4965

REGIONS = {
    "front (face to +0.075 m, z < 0.161)": lambda x: (x[:, 0] > FACE_X)
    & (x[:, 0] < FACE_X + 0.075)
    & (x[:, 2] < 0.161)
    & (abs(x[:, 1] - BOX_Y_MID) < 0.2),
    "upstream (x 1.1-1.3)": lambda x: (x[:, 0] > 1.1)
    & (x[:, 0] < 1.3)
    & (abs(x[:, 1] - BOX_Y_MID) < 0.2),
}


def snapshots(run):
    times = {}
    pvd = os.path.join(run, "series.pvd")
    if os.path.exists(pvd):
        times = {d.get("file"): float(d.get("timestep")) for d in ET.parse(pvd).iter("DataSet")}
    for f in sorted(glob.glob(os.path.join(run, "particles_*.vtp"))):
        yield times.get(os.path.basename(f), float("nan")), read_vtp(f)


def regions(run):
    print("t (s) | " + " | ".join(f"{name}: n, mean p, std p (Pa)" for name in REGIONS))
    for t, d in snapshots(run):
        x, p = d["points"], d["pressure"]
        cells = []
        for sel in REGIONS.values():
            m = sel(x)
            cells.append(f"{m.sum()}, {p[m].mean():.0f}, {p[m].std():.0f}" if m.any() else "0")
        print(f"{t:.3f} | " + " | ".join(cells))


def track(run, pid):
    print("t (s) | distance to face (m) | y | z | v (m/s) | p (Pa) | rho | drho/dt")
    for t, d in snapshots(run):
        i = np.where(d["id"] == pid)[0]
        if len(i) == 0:
            continue
        i = i[0]
        x, v = d["points"][i], d["velocity"][i]
        print(f"{t:.3f} | {x[0] - FACE_X:.4f} | {x[1]:.4f} | {x[2]:.4f} | "
              f"{v[0]:.2f} {v[1]:.2f} {v[2]:.2f} | {d['pressure'][i]:.0f} | "
              f"{d['density'][i]:.2f} | {d['density_rate'][i]:.0f}")


def main():
    if len(sys.argv) == 2:
        regions(sys.argv[1])
    elif len(sys.argv) == 4 and sys.argv[2] == "--track":
        track(sys.argv[1], int(sys.argv[3]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
