#pragma once
// The two wall terms that keep fluid particles off a wall in both boundary families (ghosts
// and boundary integrals), measured in docs/validation/free_surface/findings.md.
//
// Why they are needed. Neither family stiffens as a particle nears its wall. With ghosts the
// particle's own ghost sits at 2d and grad W(2d) -> 0 as d -> 0; for a uniform pressure p the
// fluid and image sums cancel on the wall plane, so the normal force on a first-row particle
// pushed from d = dx/2 towards the wall rises to 2 p (0.020/dx) / rho at d = 0.2 dx and falls
// linearly to 0 at the wall (lattice sum, h = 2 dx): an energy barrier of 0.013 p/rho, which a
// particle with 0.16 m/s into the wall crosses at p = 1 kPa. With boundary integrals the
// continuity equation does not compress a particle that moves towards the wall (the fluid and
// wall parts of div u cancel, integrals_boundary.cpp item 2b) and the restoring stiffness is
// of order p_i/(rho h^2). Free-surface flows (dam break, column on a cylinder) cross the
// walls with 0.1-0.3 m/s (median) of normal velocity at p of a few hundred Pa, or in tension.
//
// 1. Impact pressure (velocity). The wall pressure a particle sees is the solution of the
//    Riemann problem between the particle and its mirror image across the wall (normal
//    velocity reflected about the wall's), as in the wall condition of Zhang, Hu & Adams
//    (2017, "A weakly compressible SPH method based on a low-dissipation Riemann solver",
//    J. Comput. Phys. 335, 605-620). Its linearised (acoustic) solution, p* = (p_L + p_R)/2 +
//    rho c0 (U_L - U_R)/2 with U_R = 2 u_w.n - U_L (Toro, Riemann Solvers and Numerical
//    Methods for Fluid Dynamics, the linearised solver), is p* = p + rho c0 u_a, u_a = (u_w -
//    u_i).n the speed at which the particle approaches the wall (n into the fluid): the
//    water-hammer pressure of a rigid wall. It is added to the wall pressure of the wall pairs
//    of a particle about to touch that wall only (ghosts: p_g of its single ghosts; integrals:
//    p_b of that wall's elements), weighted by a taper of the particle's distance d to the wall
//    (wall_impact_reach below: boundary integrals full up to d = dx/4, none from 3 dx/4 on;
//    ghosts dx/2 and dx), for approach only (u_a > 0: a wall that resists compression, never
//    one that sucks a receding particle back), and without Zhang et al.'s low-dissipation limiter
//    (beta = c0). Zhang et al. apply the Riemann pressure to the wall pair of a particle and its
//    own mirror image; the ghost and integral sums spread a wall pressure over the whole kernel
//    support (2h = 4 dx at h = 2 dx), and added there without the taper it braked a surge front 2h
//    before it reached a wall: the SPHERIC-2 dam break (cases/dam_break_3d.yaml) at 0.55/15 met its
//    box 0.094 s late with a first P1 peak 5.9 times the experiment's, against 1.26 without the
//    term (docs/validation/dam_break_3d/findings.md, "The reach of the impact pressure"). Measured
//    there at 0.55/15 to t = 0.6 s (first P1 peak / experiment, lowest sensor): no taper 5.93,
//    -44 kPa; taper 0.5-1 dx 3.54, -24 kPa; 0.25-0.75 dx 2.45, -25 kPa; 0-0.5 dx 2.79, -97 kPa;
//    0.25-0.75 dx with the limiter beta = min(3 max(U_L - U_R, 0), c0) 2.48, -39 kPa and 25
//    times the wall contacts; nothing put back in any. (Without any impact pressure: 1.26, -54 kPa;
//    in 2-D the contact layer alone (at dx/4) held the walls but left the dam break's surge front
//    error at 0.15-0.17, free_surface/findings.md section 2.) Within the taper it acts as a normal
//    damper of rate ~0.33 c0/dx (2-D, h = 2 dx: sum_b W A n ~ 0.33/dx at the wall), about 0.17 per
//    time step at cfl 0.25: stable, and zero in any flow that slides along its walls. The approach
//    speed and the distance are the particle's own, along its own normal to the wall (ghosts: its
//    own ghost of that wall or face and the depth of its source; integrals: the W A-weighted mean
//    normal, velocity and normal distance (x_i - x_b).n_b of the elements near it), so that flow
//    along a curved wall has none. Taken along the normal of each neighbour's image instead (tilted
//    by the curvature, one-sided), it dragged the Couette annulus (c0 = 0.25 m/s): velocity error
//    0.085 at t = 0.3 s against < 0.05.
// 2. Contact layer (position). A particle closer than d0 (kWallLayer below) to a wall is pushed off
// it
//    with Calderon-Sanchez et al.'s wall force law (§3.2, boundary/wall_force.hpp),
//    a = (c0^2/dx) (1 - d/d0)^2 n, with d0 = dx/4 (the depth at which a particle found past a
//    wall is put back, solver/stray_particles.hpp) instead of their 0.1 dx, so that a particle
//    stops before the stray-particle contact at 0.1 dx. The first particle row sits at dx/2 and
//    never feels it; its energy barrier c0^2/12 is crossed at c0/sqrt(6) = 0.41 c0 (11-14 m/s
//    in the free-surface cases, whose largest speed is about 3.4 m/s). It holds what the impact
//    pressure cannot: a slow approach (a thin layer sinking onto the floor at a few mm/s) and
//    particles in tension pulled by the wall's pair terms at contact lines.
#include <algorithm>

#include "curvsph/core/types.hpp"

namespace curvsph {

// d0 of the contact layer (item 2), in dx. 0.1 dx (Calderon's value), not the dx/4 argued
// above: a fill packed by setup.relax leaves particles nearer a wall than dx/4, where the
// layer pushes them at rest (the packed 90 degree CornerTank: pressure error 0.091 of rho g H
// at dx/4, 0.0085 at 0.1 dx). With 0.1 dx and the impact pressure, the contact off
// (boundary.contact: 0), dam_break_2d and column_on_cylinder_2d with ghosts and with
// integrals still run to t = 1.5 s with nothing put back and no density clamped (also with
// the reach of item 1 below: dam_break_3d/findings.md, "The reach of the impact pressure").
inline constexpr Real kWallLayer = Real(0.1);

// Item 1's reach, in dx: the impact pressure acts in full on a particle up to `full` dx from
// its wall, not at all from `zero` dx on, and tapers between. The ghosts reach further: a
// particle's own ghost pushes with grad W(2d) -> 0 as d -> 0, so the impact pressure reaches
// it mostly through its neighbours' ghosts, and with the integrals' 0.25-0.75 dx the ghost
// column_on_cylinder_2d clamped the density 381 times (0 with 0.5-1 dx;
// docs/validation/dam_break_3d/findings.md, "The reach of the impact pressure").
struct ImpactReach {
  Real full, zero;
};
inline constexpr ImpactReach kImpactReachIntegrals{Real(0.25), Real(0.75)};
inline constexpr ImpactReach kImpactReachGhosts{Real(0.5), Real(1)};

// The taper: 1 at q = depth/dx <= full, 0 at q >= zero, the cubic smoothstep 3 s^2 - 2 s^3 of
// s = (zero - q)/(zero - full) between (no jump in the force as a particle crosses either
// bound).
inline Real wall_impact_reach(Real q, const ImpactReach& r) {
  if (q <= r.full) return 1;
  if (q >= r.zero) return 0;
  const Real s = (r.zero - q) / (r.zero - r.full);
  return s * s * (3 - 2 * s);
}

// Item 1: the pressure added to a wall pair of a particle of density rho approaching the wall
// at speed `approach` = (u_w - u_i).n (n into the fluid), at `depth` dx from it.
inline Real wall_impact_pressure(Real rho, Real c0, Real approach, Real depth,
                                 const ImpactReach& r) {
  return rho * c0 * std::max(approach, Real(0)) * wall_impact_reach(depth, r);
}

}  // namespace curvsph
