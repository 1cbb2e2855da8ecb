#pragma once
// Vela Vela et al. §7 (static node-density tests, Figs. 6-8): node density (eq. 3) at the
// fluid particles and at their ghosts, for the mirror and the density_preserving maps (and
// the case's own map), from the same particle set.
//
// As in the paper every fluid particle gets a ghost (`ghost_support: all`, the default; a
// number sets the depth of fluid that is mirrored), so the ghosts near the wall see a full
// kernel. n is summed over fluid particles and ghosts. n_ref is the mean n of the fluid
// particles farther than 2h from every wall (all of them when none is).
// Metrics:
//   ghost_node_density_dev[_<map>] = mean over ghosts with depth < 2h of |n_g / n_ref - 1|
//     (without suffix: the case's boundary.map),
//   node_density_ref, node_density_interior_spread (std/mean of n over the deep particles),
//   node_density_ghosts_near_wall (count).
// Files (when out_dir is set): node_density_binned.csv (map, kind, bin centre of the signed
// distance to the wall — negative behind it — mean/std/min/max of n/n_ref, count) and
// node_density_points.csv (a subsample: map, kind, distance, n/n_ref, position x0..x{D-1}).
#include <memory>

#include "curvsph/analysis/analysis.hpp"

namespace curvsph {

template <int D>
std::unique_ptr<Analysis<D>> make_node_density_analysis(const YAML::Node& params, const Case& c);

}  // namespace curvsph
