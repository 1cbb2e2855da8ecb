#pragma once
// The collapse of a liquid column on a dry floor (the classic 2-D dam break): the surge front
// against Martin & Moyce (1952, Fig. 3, n^2 = 2: a column twice as high as it is wide) and the
// run-up on the far wall. Parameters:
//   {wall: x0, width: a, far_wall: xf, experiment: PATH}
// x0: the wall behind the column (default: the initial particles' smallest x); a: the column's
// width (default: the initial particles' x extent); far_wall: the opposite wall (optional: the
// run-up height is measured there); experiment: a CSV `T,Z` with T = t sqrt(2 g/a), Z = x/a
// (optional; data/martin_moyce/), relative to the case file.
// The front is the largest x of the particles on the floor (within 2 dx of the lowest particle
// level: a droplet thrown ahead above the floor is not the front), until it reaches the far wall.
// Figures: surge_front_points (experiment points within the simulated range, before the far
// wall), surge_front_max_rel_error and surge_front_rms_rel_error (|Z - Z_exp|/Z_exp over those
// points, Z interpolated linearly in time between outputs), surge_front_t_far_wall (reduced time
// T when the front reaches the far wall, NaN if never), far_wall_runup_max (largest height of a
// particle within 2 dx of the far wall, over the column's height 2a). Writes surge_front.csv
// (T, Z, the far-wall height over 2a) at every output time.
#include "curvsph/analysis/analysis.hpp"

namespace curvsph {

std::unique_ptr<Analysis<2>> make_surge_front_analysis(const YAML::Node& params, const Case& c);

}  // namespace curvsph
