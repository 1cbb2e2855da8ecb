#!/usr/bin/env python3
"""Diagnostics of a throttled-pipe particle state (curvsph .vtp output) used in
docs/validation/throttled_pipe/findings.md:

    /usr/bin/python3 scripts/throttled_pipe_particles.py flux     VTP...   # Q = sum(m/rho u_x) / L_x
    /usr/bin/python3 scripts/throttled_pipe_particles.py noise    VTP...   # fluctuations, |x| > 10 mm
    /usr/bin/python3 scripts/throttled_pipe_particles.py profile  VTP      # u_x across seam and throat
    /usr/bin/python3 scripts/throttled_pipe_particles.py moments  VTP H [flat|mild]

`moments`: second moment of curvsph's viscous sum (DESIGN.md §4) on the actual particles,
M_i = -1/2 sigma_i sum_j (1/sigma_i^2 + 1/sigma_j^2) F_ij x_ij x_ij^T with F = (1/r) dW/dr, so
that the sum returns M : grad grad u (exact: M = I), and the first-moment error
b_i = sigma_i sum_j (1/sigma_i^2 + 1/sigma_j^2) F_ij x_ij (exact: 0; printed as rms |b_y| h),
for particles farther than 2h from both walls (no ghosts needed), in 2 mm bins of |x|.
Geometry: cases/throttled_pipe.yaml (L_x = 0.024, the B-spline walls; `flat`/`mild` are the
variants of the findings: all control points at -+0.005, or halfway to that).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtp import read_vtp  # noqa: E402  (raw or zlib, Float64 or Float32)

LX = 0.024


def flux(paths):
    for p in paths:
        d = read_vtp(p)
        vol = d["mass"] / d["density"]
        print(f"{p}: N = {len(vol)}  Q = {np.sum(vol * d['velocity'][:, 0]) / LX:.6e} m^2/s  "
              f"area = {vol.sum():.6e} m^2  mean p = {d['pressure'].mean():.2f} Pa")


def noise(paths):
    for p in paths:
        d = read_vtp(p)
        x, y, u, pr = d["points"][:, 0], d["points"][:, 1], d["velocity"], d["pressure"]
        m = np.abs(x) > 0.010  # the straight part of every variant
        band = np.floor(y[m] / 0.0005).astype(int)
        res = {}
        for name, v in (("u_x", u[m, 0]), ("u_y", u[m, 1]), ("p", pr[m])):
            dv = np.zeros_like(v)
            for b in np.unique(band):
                s = band == b
                dv[s] = v[s] - v[s].mean()
            res[name] = math.sqrt(float(np.mean(dv**2)))
        print(f"{p}: |x| > 10 mm: mean u_x = {u[m, 0].mean():.4f}  rms du_x = {res['u_x']:.4f}  "
              f"rms du_y = {res['u_y']:.4f}  rms dp = {res['p']:.2f} Pa  mean p = {pr[m].mean():.2f}")


def profile(path):
    d = read_vtp(path)
    x, y, u = d["points"][:, 0], d["points"][:, 1], d["velocity"][:, 0]
    for name, x0, half in (("seam", 0.012, 0.005), ("throat", 0.0, 0.0025)):
        m = np.abs((x - x0 + LX / 2) % LX - LX / 2) < 0.0006
        edges = np.linspace(-half, half, 11)
        k = np.digitize(y[m], edges) - 1
        print(name, " ".join(f"{(edges[i] + edges[i + 1]) / 2e-3:+.2f}:{u[m][k == i].mean():.4f}"
                             for i in range(10) if (k == i).any()))


def walls(variant):
    from scipy.interpolate import BSpline
    cy = [-0.005] * 5 + [-0.0046, -0.0037, -0.00275, -0.002375, -0.00275, -0.0037, -0.0046] + [-0.005] * 5
    if variant == "flat":
        cy = [-0.005] * 17
    elif variant == "mild":
        cy = [-0.005 + 0.5 * (v + 0.005) for v in cy]
    knots = np.array([0, 0, 0, 0] + list(range(1, 14)) + [14, 14, 14, 14], float)
    t = np.linspace(0, 14, 20001)
    wx = BSpline(knots, np.linspace(-0.016, 0.016, 17), 3)(t)
    wy = BSpline(knots, np.array(cy), 3)(t)
    return np.stack([wx, wy], 1), np.stack([wx, -wy], 1)


def moments(path, h, variant):
    d = read_vtp(path)
    x, sig = d["points"][:, :2], d["density"] / d["mass"]  # sigma = rho / m
    bottom, top = walls(variant)
    alpha = 7 / (4 * math.pi * h * h)  # Wendland C2, 2-D (DESIGN.md §4)
    bins = {}
    for i in range(len(x)):
        if min(np.min(np.hypot(*(bottom - x[i]).T)), np.min(np.hypot(*(top - x[i]).T))) < 2 * h:
            continue
        r = x[i] - x
        r[:, 0] -= LX * np.round(r[:, 0] / LX)
        dist = np.hypot(r[:, 0], r[:, 1])
        m = (dist < 2 * h) & (dist > 0)
        q = dist[m] / h
        f = alpha * (-5 * q) * (1 - q / 2) ** 3 / h / dist[m]
        c = sig[i] * (1 / sig[i] ** 2 + 1 / sig[m] ** 2) * f
        M = -0.5 * np.einsum("k,ka,kb->ab", c, r[m], r[m])
        b = np.einsum("k,ka->a", c, r[m]) * h
        bins.setdefault(int(abs(x[i, 0]) / 0.002), []).append((M[0, 0], M[1, 1], M[0, 1], b[1]))
    print(f"{path}: |x| (mm)  M_xx   M_yy   M_xy    rms b_y h  particles  (exact: M = I, b = 0)")
    for k in sorted(bins):
        a = np.array(bins[k])
        print(f"  {2 * k:2d}-{2 * k + 2:2d}    {a[:, 0].mean():.3f}  {a[:, 1].mean():.3f}  "
              f"{a[:, 2].mean():+.3f}  {math.sqrt(np.mean(a[:, 3] ** 2)):.3f}      {len(a)}")


if __name__ == "__main__":
    cmd, args = sys.argv[1], sys.argv[2:]
    if cmd == "flux":
        flux(args)
    elif cmd == "noise":
        noise(args)
    elif cmd == "profile":
        profile(args[0])
    elif cmd == "moments":
        moments(args[0], float(args[1]), args[2] if len(args) > 2 else "case")
    else:
        sys.exit(__doc__)
