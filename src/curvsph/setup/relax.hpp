#pragma once
// Particle packing (`setup: {relax: {max_steps, tolerance, map}}`): drives the initial
// particles toward uniform node density inside any wall set, with the walls active through
// ghosts of a ghost map (SPHinXsys / ALARIC-style relaxation).
//
// Node density (Vela Vela eq. 3): n_i = sum_j W_ij over fluid particles plus
// sum_g beta_g W_ig over the ghosts (beta = 1 for mirror and density_preserving).
// Spread: std(n)/mean(n) over the fluid particles.
//
// One pseudo-time step: ghosts are rebuilt from the current positions, n_i and its gradient
// g_i = sum_j grad W_ij (+ ghosts) are summed, and every particle moves down the gradient,
// dx_i = -alpha h^2 g_i / mean(n) (a damped, first-order flow: no velocity is kept), the step
// capped at `max_shift` dx. Particles found on the wrong side of a wall (or closer than
// `wall_clearance` dx) are put back at that clearance along the wall normal. Stops when the
// spread falls below `tolerance` or after `max_steps` steps.
#include <string>
#include <vector>

#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/core/types.hpp"
#include "curvsph/geometry/wall.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph {

struct RelaxOptions {
  long max_steps = 2000;
  double tolerance = 1e-3;
  GhostMapKind map = GhostMapKind::density_preserving;
  double dx = 0;
  double alpha = 0.25;          // step factor of dx = -alpha h^2 grad n / mean n
  double max_shift = 0.2;       // largest move per step, in dx
  double wall_clearance = 0.1;  // smallest distance to a wall after a step, in dx
};

struct RelaxResult {
  long steps = 0;
  double spread_initial = 0;  // before the first step
  double spread = 0;          // at the final positions
  double seconds = 0;
  // n_i at the final positions (fluid and ghosts); the solver takes it for the masses.
  std::vector<Real> node_density;
};

// n at each point of `at` from the fluid points xf (cell list cf, built over xf) and the
// ghosts G (cell list cg, built over G.x; may be null when there are no walls).
template <int D>
void node_density(const std::vector<Vec<D>>& at, const std::vector<Vec<D>>& xf,
                  const CellList<D>& cf, const GhostSet<D>* G, const CellList<D>* cg,
                  const WendlandC2<D>& W, std::vector<Real>& n);

// std/mean of v.
double relative_spread(const std::vector<Real>& v);

// One packing move, shared by both packers: x += d with |d| capped at `cap` (a particle never
// jumps across the wall in one step), then pushed back to at least `clearance` on the fluid
// side of `wall`.
template <int D>
void pack_move(Vec<D>& x, Vec<D> d, Real cap) {
  const Real len = d.norm();
  if (len > cap) d *= cap / len;
  x += d;
}
template <int D>
void keep_clear_of(Vec<D>& x, const Wall<D>& wall, double clearance) {
  const WallPoint<D> p = wall.closest(x.template cast<double>());
  if (p.distance < clearance) x = (p.foot + clearance * p.normal).template cast<Real>();
}

// Relaxes x in place. `cells` must be configured (support 2h, domain periodicity); it is
// rebuilt over x. The walls' ghosts use `options.map` with support 2h.
template <int D>
RelaxResult relax_particles(std::vector<Vec<D>>& x, const WallSet<D>& walls, CellList<D>& cells,
                            const WendlandC2<D>& W, const RelaxOptions& options);

}  // namespace curvsph
