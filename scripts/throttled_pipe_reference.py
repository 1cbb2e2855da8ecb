#!/usr/bin/env python3
"""Independent reference for the throttled pipe (cases/throttled_pipe.yaml, Barker §4.1):
the steady flux Q (per unit depth) of the same channel and body force, computed with a
D2Q9 lattice-Boltzmann solver (BGK, Guo et al. 2002 forcing, Bouzidi et al. 2001 linear
interpolated bounce-back on the exact B-spline walls, periodic in x). Shares no code with
curvsph: the walls are evaluated with scipy's BSpline from the case's control points.

    /usr/bin/python3 scripts/throttled_pipe_reference.py NY G T_END [TAU [BUMP [PROFILES_CSV]]]

NY: lattice nodes across the wide section (L_y = 0.01 m); G: body force per unit mass
(m/s^2); T_END: simulated seconds (the slowest viscous mode decays as exp(-t/1 s));
TAU: BGK relaxation time (1.0 default). BUMP: scales the walls' departure from y = -+L_y/2
(1 default: the case's walls; 0: a plane channel, Q = g L_y^3 / (12 nu); 0.5: the "mild" variant
of docs/validation/throttled_pipe/findings.md). Prints Q and Re = rho Q / mu every tenth of the run.
PROFILES_CSV: writes the final u_x on the midline y = 0 (193 stations x = -L_x/2 + k L_x/192, the
analysis' midline) and across the throat x = 0 (65 stations from wall to wall), the `line,x,y,u_x`
rows that `curvsph validate throttled_pipe` compares the SPH profiles with
(docs/validation/throttled_pipe/lb_profiles.csv, ny = 100).
"""
import sys

import numpy as np
from scipy.interpolate import BSpline

ny = int(sys.argv[1])
g = float(sys.argv[2])
t_end = float(sys.argv[3])
tau = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
bump = float(sys.argv[5]) if len(sys.argv) > 5 else 1.0
Lx, Ly, mu, rho0 = 0.024, 0.01, 0.01, 1000.0
nu = mu / rho0
# Bottom wall of cases/throttled_pipe.yaml (cubic, clamped uniform knots); the top wall is
# its mirror image y -> -y.
cy = [-0.005] * 5 + [-0.0046, -0.0037, -0.00275, -0.002375, -0.00275, -0.0037, -0.0046] + [-0.005] * 5
cy = [-0.005 + bump * (v + 0.005) for v in cy]
cx = np.linspace(-0.016, 0.016, 17)
knots = np.array([0, 0, 0, 0] + list(range(1, 14)) + [14, 14, 14, 14], float)
tt = np.linspace(0, 14, 400001)
wx, wy = BSpline(knots, cx, 3)(tt), BSpline(knots, np.array(cy), 3)(tt)


def y_bottom(x):
    return np.interp(x, wx, wy)  # x(t) is monotone; 4e5 samples: < 1e-10 m


dx = Ly / ny
nx = int(round(Lx / dx))
pad = 2
xs = -Lx / 2 + (np.arange(nx) + 0.5) * dx
ys = -Ly / 2 + (np.arange(-pad, ny + pad) + 0.5) * dx
X, Y = np.meshgrid(xs, ys, indexing="ij")


def wall_fn(x, y):  # > 0 in the fluid
    return np.minimum(y - y_bottom(x), -y_bottom(x) - y)


solid = wall_fn(X, Y) <= 0
fluid = ~solid
nu_l = (tau - 0.5) / 3
dt = nu_l * dx**2 / nu
g_l = g * dt**2 / dx
c = np.array([[0, 0], [1, 0], [0, 1], [-1, 0], [0, -1], [1, 1], [-1, 1], [-1, -1], [1, -1]])
w = np.array([4 / 9] + [1 / 9] * 4 + [1 / 36] * 4)
opp = [0, 3, 4, 1, 2, 7, 8, 5, 6]

# Boundary links: fluid node -> solid neighbour along c_i, with the wall at fraction q.
links = []
for i in range(1, 9):
    nb_solid = np.roll(np.roll(solid, -c[i, 0], 0), -c[i, 1], 1)
    ix, iy = np.nonzero(fluid & nb_solid)
    x0, y0 = X[ix, iy], Y[ix, iy]
    lo, hi = np.zeros(len(ix)), np.ones(len(ix))
    for _ in range(50):  # bisection on the exact wall
        m = 0.5 * (lo + hi)
        inside = wall_fn(x0 + m * c[i, 0] * dx, y0 + m * c[i, 1] * dx) > 0
        lo = np.where(inside, m, lo)
        hi = np.where(inside, hi, m)
    q = 0.5 * (lo + hi)
    bx, by = (ix - c[i, 0]) % nx, iy - c[i, 1]  # the node behind x (for q < 1/2)
    links.append((i, ix, iy, q, bx, by))


def feq(rho, ux, uy):
    cu = c[:, 0, None, None] * ux + c[:, 1, None, None] * uy
    return w[:, None, None] * rho * (1 + 3 * cu + 4.5 * cu**2 - 1.5 * (ux**2 + uy**2))


# Start from the lubrication flow of the force (local Poiseuille profiles).
R = -y_bottom(xs)
Q_lub = 2 * g * Lx / (3 * nu * np.sum(R**-3) * dx)
eta = np.clip(Y / R[:, None], -1, 1)
ux = np.where(solid, 0.0, 3 * Q_lub / (4 * R[:, None]) * (1 - eta**2)) * dt / dx
f = feq(np.ones_like(ux), ux, np.zeros_like(ux))
steps = int(round(t_end / dt))
print(f"ny={ny} nx={nx} tau={tau} dt={dt:.3e} s steps={steps} lubrication Q={Q_lub:.5e}")
for s in range(steps + 1):
    rho = f.sum(0)
    # Guo et al. 2002 (eqs. 20, 22): the force density is F = rho g, the body force per unit
    # mass times the local density, so u = (sum f c + F/2) / rho = sum f c / rho + g/2.
    # (F = g, a force per unit volume at rho = 1, drives a fluid whose lattice density has
    # drifted below 1 -- the interpolated bounce-back does not conserve mass -- harder than g:
    # at ny = 50 the flux then crept up 0.1 % per 0.6 s with no end.)
    ux = (f * c[:, 0, None, None]).sum(0) / rho + 0.5 * g_l
    uy = (f * c[:, 1, None, None]).sum(0) / rho
    ux[solid] = 0
    uy[solid] = 0
    if s % max(1, steps // 10) == 0 or s == steps:
        Q = ux[fluid].sum() * dx**3 / dt / Lx  # mean over x of the section flux
        print(f"t={s * dt:.3f} Q={Q:.6e} Re={rho0 * Q / mu:.3f} "
              f"u_max={ux.max() * dx / dt:.5f}", flush=True)
    if s == steps:
        break
    cu = c[:, 0, None, None] * ux + c[:, 1, None, None] * uy
    force = (1 - 0.5 / tau) * w[:, None, None] * (
        3 * (c[:, 0, None, None] - ux) + 9 * cu * c[:, 0, None, None]) * g_l * rho
    fp = f - (f - feq(rho, ux, uy)) / tau + force
    for i in range(9):
        f[i] = np.roll(np.roll(fp[i], c[i, 0], 0), c[i, 1], 1)
    for i, ix, iy, q, bx, by in links:  # Bouzidi linear interpolated bounce-back
        o = opp[i]
        small = q < 0.5
        a = np.where(small, 2 * q * fp[i, ix, iy] + (1 - 2 * q) * fp[i, bx, by],
                     fp[i, ix, iy] / (2 * q) + (2 * q - 1) / (2 * q) * fp[o, ix, iy])
        f[o, ix, iy] = a


if len(sys.argv) > 6:  # the profiles: u_x of each column's fluid nodes with u = 0 on its walls,
    # linear in y within a column and in x between the two columns around x (periodic)
    u_ms = ux * dx / dt

    def column(k, y):
        k %= nx
        m = fluid[k]
        yy = np.concatenate([[y_bottom(xs[k])], Y[k, m], [-y_bottom(xs[k])]])
        return np.interp(y, yy, np.concatenate([[0.0], u_ms[k, m], [0.0]]))

    def u_at(x, y):
        s = (x + Lx / 2) / dx - 0.5
        k = int(np.floor(s))
        a = s - k
        return (1 - a) * column(k, y) + a * column(k + 1, y)

    with open(sys.argv[6], "w") as out:
        out.write("line,x,y,u_x\n")
        for k in range(193):
            x = -Lx / 2 + k * Lx / 192
            out.write(f"midline,{x:.9g},0,{u_at(x, 0.0):.9g}\n")
        R0 = -y_bottom(0.0)
        for k in range(65):
            y = -R0 + 2 * R0 * k / 64
            out.write(f"throat,0,{y:.9g},{u_at(0.0, y):.9g}\n")
