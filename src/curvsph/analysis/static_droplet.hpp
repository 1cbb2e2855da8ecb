#pragma once
#include "curvsph/analysis/analysis.hpp"

namespace curvsph {

// A drop at rest in another fluid (issue #6): the Laplace pressure jump against s/R (2-D) or
// 2s/R (3-D) from the case's first surface-tension pair (drop = its second fluid, a disk or
// ball region). Figures: laplace_pressure (inside minus outside, inside over r < R/2, outside
// over r > R + 4h), laplace_pressure_reference, laplace_pressure_rel_error,
// max_spurious_velocity (max |v| at the end).
template <int D>
std::unique_ptr<Analysis<D>> make_static_droplet_analysis(const YAML::Node& params, const Case& c);

}  // namespace curvsph
