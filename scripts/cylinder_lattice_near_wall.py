"""Closest approach of the fluid to the cylinder_lattice obstacle in a run's VTK snapshots
(the diagnosis in docs/validation/cylinder_lattice/findings.md).

Usage: cylinder_lattice_near_wall.py DX RUN_DIR [RUN_DIR ...]
  RUN_DIR: the --out folder of `curvsph run cases/cylinder_lattice.yaml --set output.vtk=true`.
Prints per snapshot the minimum (r - R)/dx, that particle's density, how many particles lie
within dx/4 of the wall and the mean density within dx of the wall."""
import glob
import re
import sys

import numpy as np

R = 0.2


def read_vtp(p):
    """Arrays of a curvsph .vtp file (raw appended data, UInt64 headers)."""
    b = open(p, "rb").read()
    head = b[: b.index(b"<AppendedData")].decode()
    base = b.index(b"_", b.index(b"<AppendedData")) + 1
    out = {}
    pat = (r'<DataArray type="(\w+)" Name="(\w+)"(?: NumberOfComponents="(\d)")? '
           r'format="appended" offset="(\d+)"')
    for m in re.finditer(pat, head):
        t, name, nc, off = m.group(1), m.group(2), int(m.group(3) or 1), int(m.group(4))
        n = int(np.frombuffer(b[base + off: base + off + 8], dtype="<u8")[0])
        dt = {"Float64": "<f8", "Int32": "<i4", "Int64": "<i8"}[t]
        a = np.frombuffer(b[base + off + 8: base + off + 8 + n], dtype=dt)
        out[name] = a.reshape(-1, nc) if nc > 1 else a
    return out


dx = float(sys.argv[1])
for d in sys.argv[2:]:
    print(d)
    for p in sorted(glob.glob(d + "/particles_*.vtp")):
        v = read_vtp(p)
        x = v["Points"]
        s = (np.hypot(x[:, 0], x[:, 1]) - R) / dx
        k = np.argmin(s)
        rho = v["density"]
        print(f"  {p.split('/')[-1]:24s} min (r-R)/dx = {s[k]:+.4f} (rho {rho[k]:.4f})  "
              f"n(<dx/4) = {(s < 0.25).sum():2d}  mean rho within dx = {rho[s < 1].mean():.4f}")
