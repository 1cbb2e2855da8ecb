#pragma once
// Vela Vela et al. §8 (flow through a lattice of cylinders): the run's t_max (eq. 37) = the
// end time, or the time of the first wall penetration, or of a blow-up (NaN, density out of
// range) — the run records the event and ends normally instead of exit code 3.
// Metrics: t_max, penetrations (particles through the wall at the event; 0 without),
// blowup (0/1), mean_vx (mean x velocity of the fluid at the end),
// mean_vx_rel_change_last_interval (|change of mean_vx| / mean_vx over the last output
// interval, mean_vx_last_interval long: the steady-state indicator of Fig. 9).
// Files (when out_dir is set): velocity.csv (x, y, vx, vy of every particle at the end),
// history.csv (t, mean v_x at every output time).
#include <memory>

#include "curvsph/analysis/analysis.hpp"

namespace curvsph {

std::unique_ptr<Analysis<2>> make_cylinder_lattice_analysis(const YAML::Node& params,
                                                            const Case& c);

}  // namespace curvsph
