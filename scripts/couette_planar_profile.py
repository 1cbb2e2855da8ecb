"""Mean profile of a plane Couette snapshot (docs/validation/couette/planar_couette.yaml).

Usage: couette_planar_profile.py PARTICLES.vtp [GAP_M] [U_MPS] [BINS]
Prints u_x / U and y / GAP for each of BINS equal bins across the gap (one per particle row
of the lattice by default), and the rms of u_x - U y / GAP over U.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp import read_vtp  # noqa: E402


def main():
    path = sys.argv[1]
    gap = float(sys.argv[2]) if len(sys.argv) > 2 else 0.015
    u_wall = float(sys.argv[3]) if len(sys.argv) > 3 else 0.025
    bins = int(sys.argv[4]) if len(sys.argv) > 4 else 8
    d = read_vtp(path)
    y = d["points"][:, 1]
    u = d["velocity"][:, 0]
    k = np.clip((y / gap * bins).astype(int), 0, bins - 1)
    print("y/gap  u/U  (exact u/U = y/gap)")
    for b in range(bins):
        s = k == b
        if np.any(s):
            print(f"{y[s].mean() / gap:.3f}  {u[s].mean() / u_wall:.3f}")
    print(f"rms(u - U y/gap) / U = {np.sqrt(np.mean((u - u_wall * y / gap) ** 2)) / u_wall:.4f}")


if __name__ == "__main__":
    main()
