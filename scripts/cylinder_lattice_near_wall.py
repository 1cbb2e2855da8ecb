"""Closest approach of the fluid to the cylinder_lattice obstacle in a run's VTK snapshots
(the diagnosis in docs/validation/cylinder_lattice/findings.md).

Usage: cylinder_lattice_near_wall.py DX RUN_DIR [RUN_DIR ...]
  RUN_DIR: the --out folder of `curvsph run cases/cylinder_lattice.yaml --set output.vtk=true`.
Prints per snapshot the minimum (r - R)/dx, that particle's density, how many particles lie
within dx/4 of the wall and the mean density within dx of the wall."""
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp import read_vtp  # noqa: E402  (raw or zlib, Float64 or Float32)

R = 0.2


dx = float(sys.argv[1])
for d in sys.argv[2:]:
    print(d)
    for p in sorted(glob.glob(d + "/particles_*.vtp")):
        v = read_vtp(p)
        x = v["points"]
        s = (np.hypot(x[:, 0], x[:, 1]) - R) / dx
        k = np.argmin(s)
        rho = v["density"]
        print(f"  {p.split('/')[-1]:24s} min (r-R)/dx = {s[k]:+.4f} (rho {rho[k]:.4f})  "
              f"n(<dx/4) = {(s < 0.25).sum():2d}  mean rho within dx = {rho[s < 1].mean():.4f}")
