#pragma once
#include "curvsph/analysis/analysis.hpp"

namespace curvsph {

// Barker & Neethling §4.2 (issue #6): a drop (the second fluid of the first surface-tension
// pair) on a wall with a contact angle, 2-D. At every output time the two contact angles are
// measured from the interface shape (contact_angle_fit.hpp: circle fit to the interface points
// within fit_radius_dx * dx of each contact point, by default (0) within half the distance
// between the two contact points, intersected with the wall, angle inside the drop). Figures:
// contact_angle_deg_left/_right and their mean contact_angle_deg at the end,
// contact_angle_initial_deg (mean at t = 0, to show the drop moved), contact_angle_imposed_deg
// (the wall's contact_angle at the contact points), contact_angle_error_deg (the larger of
// the two |measured - imposed|), droplet_mass_change (|M_end - M_0| / M_0 of the drop phase),
// wall_crossings (particles on the wall's far side at any output time).
// Writes contact_angle_history.csv (t, left, right), droplet_particles.csv (x, y, drop) and
// droplet_fit.csv (the fitted circles and contact points) into the run directory.
// Params: {fit_radius_dx: 0}.
template <int D>
std::unique_ptr<Analysis<D>> make_droplet_wall_analysis(const YAML::Node& params, const Case& c);

}  // namespace curvsph
