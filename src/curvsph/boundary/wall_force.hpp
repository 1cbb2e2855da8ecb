#pragma once
// The short-range wall force of `boundary.wall_force` (Calderon-Sanchez et al. §3.2: a
// boundary force "triggered when a fluid particle moves closer than 0.1 dr to the wall", added
// "to avoid walls penetration"). For a particle at distance d < d0 = 0.1 dx from a wall whose
// unit normal n points into the fluid,
//   a = (c0^2 / dx) (1 - d/d0)^2 n,
// a pressure-like stiffness (c0^2 times a strain over the particle spacing) that vanishes with
// its derivative at d0. It is a safeguard, not part of either boundary treatment: the boundary
// integrals and the ghosts both hold a particle off a wall by pressure only, and both pull a
// particle in tension (p < 0) towards the wall (the symmetric pair form p_i + p_wall), which is
// how free-surface contact lines cross walls without it (findings of the 3-D dam break).
#include <algorithm>
#include <cstddef>

#include "curvsph/core/types.hpp"
#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

struct WallForce {
  Real stiffness = 0;  // c0^2 / dx
  Real range = 0;      // d0 = 0.1 dx

  WallForce() = default;
  WallForce(Real c0, Real dx, Real fraction = Real(0.1))
      : stiffness(c0 * c0 / dx), range(fraction * dx) {}

  bool active(Real d) const { return range > 0 && d < range; }

  // Acceleration magnitude along the wall normal at distance d (d <= 0 is the wall itself:
  // the solver reports such a particle as penetrated).
  Real magnitude(Real d) const {
    if (!active(d)) return 0;
    const Real s = 1 - std::max(d, Real(0)) / range;
    return stiffness * s * s;
  }
};

// The push on a particle at x from every wall closer than the law's range, face by face for a
// box with the fluid inside (a particle in a corner of a tank is pushed off the floor and the
// side wall at once; the nearest wall alone would let it sink into the farther one), the
// nearest point of any other wall: f(k, push, foot) for each wall k that pushes, with the
// foot point it pushes from (the wall loads take its reaction there).
template <int D, class F>
void wall_force_each(const WallSet<D>& walls, const Vec<D>& xi, const WallForce& law, F&& f) {
  const VecD<D> x = xi.template cast<double>();
  const double range = static_cast<double>(law.range);
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const auto* box = dynamic_cast<const BoxWall<D>*>(&walls[k]);
    if (box && box->side() == FluidSide::inside) {
      for (int a = 0; a < D; ++a) {
        const double lo = x[a] - box->min()[a], hi = box->max()[a] - x[a];
        VecD<D> foot = x;
        if (lo < range) {
          foot[a] = box->min()[a];
          f(k, Vec<D>(law.magnitude(static_cast<Real>(lo)) * Vec<D>::Unit(a)), foot);
        }
        if (hi < range) {
          foot[a] = box->max()[a];
          f(k, Vec<D>(-law.magnitude(static_cast<Real>(hi)) * Vec<D>::Unit(a)), foot);
        }
      }
      continue;
    }
    if (walls[k].distance_lower_bound(x) >= range) continue;
    const WallPoint<D> p = walls[k].closest(x);
    if (p.distance < range)
      f(k, Vec<D>(law.magnitude(static_cast<Real>(p.distance)) * p.normal.template cast<Real>()),
        p.foot);
  }
}

// The sum of wall_force_each's pushes.
template <int D>
Vec<D> wall_force_push(const WallSet<D>& walls, const Vec<D>& xi, const WallForce& law) {
  Vec<D> push = Vec<D>::Zero();
  wall_force_each(walls, xi, law, [&](std::size_t, const Vec<D>& p, const VecD<D>&) { push += p; });
  return push;
}

}  // namespace curvsph
