#pragma once
// Vela Vela et al. §7 (static node-density tests, Figs. 6-8): node density (eq. 3) at the
// fluid particles and at their ghosts, for the mirror and the density_preserving maps (and
// the case's own map), from the same particle set.
//
// Two source bands, both measured, from the same particles:
//  - the analysis band (`ghost_support: all`, the default; a number sets the depth of fluid
//    that is mirrored): as in the paper ("50K ghost particles were used to guarantee that
//    every internal particle has a ghost counterpart", §7.1), every fluid particle gets a
//    ghost, so a ghost near the wall sees the ghosts of the deep fluid too. Sources for which
//    the map has no root (a deep particle behind a small convex obstacle with
//    density_preserving, DESIGN.md §4) get no ghost and are counted, never refused: the
//    set-up refusal (check_ghost_walls) concerns the solver's 2h band only and is not called
//    here;
//  - the solver band: only fluid particles within 2h of a wall are mirrored (what the solver
//    builds every step). A ghost deeper than about (shell thickness - 2h) then misses part
//    of its own support, so its n is low by construction; the solver never uses a ghost's n
//    (the ghost copies its source's), only the fluid's, reported as fluid_node_density_dev.
// n is summed over fluid particles and ghosts. n_ref is the mean fluid-only n of the fluid
// particles farther than 2h from every wall (all of them when none is).
// Metrics (<map>: mirror, density_preserving, and the case's map when it is mirror_beta):
//   ghost_node_density_dev[_<map>] = mean over ghosts with depth < 2h of |n_g / n_ref - 1|,
//     analysis band (without suffix: the case's boundary.map) — the figure;
//   ghost_node_density_dev_solver_band[_<map>]: the same over the solver band's ghosts;
//   fluid_node_density_dev[_solver_band]_<map>: mean |n_f / n_ref - 1| over fluid particles
//     within 2h of a wall;
//   node_density_ghosts[_solver_band]_<map> (count), node_density_sources_without_ghost_<map>
//     (analysis band: penetrated or no root), node_density_ref, node_density_interior_spread
//     (std/mean of n over the deep particles), node_density_ghosts_near_wall (count).
// Files (when out_dir is set): node_density_binned.csv (map, kind, bin centre of the signed
// distance to the wall — negative behind it — mean/std/min/max of n/n_ref, count, band) and
// node_density_points.csv (a subsample: map, kind, distance, n/n_ref, position x0..x{D-1},
// band); band is "all" (analysis band) or "solver" (2h).
#include <memory>
#include <vector>

#include "curvsph/analysis/analysis.hpp"
#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/geometry/wall.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph {

template <int D>
std::unique_ptr<Analysis<D>> make_node_density_analysis(const YAML::Node& params, const Case& c);

// Depth of the fluid that the analysis mirrors, from `analysis.node_density` params:
// +inf for `ghost_support: all` or when absent (Vela Vela §7: every particle), else the
// positive number given; InputError(file, ...) otherwise.
double node_density_source_band(const YAML::Node& params, const std::string& file);

// Ghosts of the fluid particles x closer than `source_band` to a wall under `map`, and n
// (Vela Vela eq. 3, over the fluid particles and these ghosts) at the ghosts and at the fluid
// particles. `cells` must already be built over x; the ghost cell list takes its box from it.
template <int D>
struct GhostNodeDensity {
  GhostSet<D> ghosts;
  CellList<D> ghost_cells;
  std::vector<Real> n_ghost, n_fluid;
};

template <int D>
void ghost_node_density(const std::vector<Vec<D>>& x, const CellList<D>& cells,
                        const WallSet<D>& walls, GhostMapKind map, double source_band,
                        const WendlandC2<D>& W, GhostNodeDensity<D>& out);

}  // namespace curvsph
