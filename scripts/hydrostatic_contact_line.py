"""Mean of a particle field binned by distance to the nearer side wall and depth below the
free surface, from one snapshot of the hydrostatic tank (docs/validation/hydrostatic_tank/
findings.md, commit d38136d: the motion at the contact lines).

    /usr/bin/python3 scripts/hydrostatic_contact_line.py RUN/particles_000010.vtp velocity 1 [DX]

FIELD is a point array of the .vtp (velocity, acceleration, pressure, ...), COMPONENT its
component (0: x, 1: y; ignored for scalars). For x components the sign is flipped on the right
half, so that positive means away from the nearer wall. Bins in units of DX (default 1/140).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp import read_vtp  # noqa: E402

path, field, comp = sys.argv[1], sys.argv[2], int(sys.argv[3])
dx = float(sys.argv[4]) if len(sys.argv) > 4 else 1 / 140
d = read_vtp(path)
x = d["points"]
v = d[field][:, comp] if d[field].ndim > 1 else d[field]
if d[field].ndim > 1 and comp == 0:
    v = v * np.where(x[:, 0] < 0.5, 1, -1)
depth = x[:, 1].max() - x[:, 1]
wall = np.minimum(x[:, 0], 1 - x[:, 0])
cols = [0, 1, 2, 3, 4, 6, 8, 12, 16, 24, 40]
rows = [0, 1, 2, 3, 4, 6, 8, 12, 16, 24]
print("depth/dx \\ wall distance/dx", " ".join(f"{c:>8d}" for c in cols[:-1]))
for r0, r1 in zip(rows[:-1], rows[1:]):
    in_row = (depth >= r0 * dx) & (depth < r1 * dx)
    cells = []
    for c0, c1 in zip(cols[:-1], cols[1:]):
        m = in_row & (wall >= c0 * dx) & (wall < c1 * dx)
        cells.append(f"{v[m].mean():8.4f}" if m.any() else "       -")
    print(f"{r0:3d}-{r1:<3d}                     ", " ".join(cells))
