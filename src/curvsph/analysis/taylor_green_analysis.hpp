#pragma once
#include "curvsph/analysis/analysis.hpp"
#include "curvsph/analysis/taylor_green.hpp"

namespace curvsph {

// The Taylor–Green reference of a case: L from the periodic domain, nu from fluid 0.
TaylorGreen taylor_green_from_case(const Case& c, const YAML::Node& params, const std::string& key);

// Figures: l2_velocity_error (relative L2 at the end), decay_rate_rel_error (kinetic energy
// decay rate fitted over the run against 4 nu k^2), decay_rate, decay_rate_reference.
std::unique_ptr<Analysis<2>> make_taylor_green_analysis(const YAML::Node& params, const Case& c);
void taylor_green_initial(const Case& c, const YAML::Node& params, const Eos& eos,
                          const std::vector<Real>& rho0, Particles<2>& P);

}  // namespace curvsph
