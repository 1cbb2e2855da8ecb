#pragma once
// `analysis: {poiseuille: {}}`: plane Poiseuille flow between two parallel `plane` walls
// (2-D). The reference is computed from the case itself: the wall distance H and the flow
// direction from the walls, nu from fluid 0, the driving acceleration from `gravity` (its
// component along the walls) and `forcing.drive` (then the profile is the cosh solution of
// channel_flows.hpp), wall speeds from `motion: {translate}` (Couette–Poiseuille).
#include "curvsph/analysis/analysis.hpp"
#include "curvsph/analysis/channel_flows.hpp"

namespace curvsph {

struct ChannelSetup {
  ChannelFlow flow;
  Vec2d origin = Vec2d::Zero();  // a point of the first wall (y = 0)
  Vec2d normal = Vec2d::Zero();  // unit, from the first wall into the fluid
  Vec2d along = Vec2d::Zero();   // unit flow direction
};

ChannelSetup channel_from_case(const Case& c, const std::string& key);

// Figures at the end: velocity_l2_error = sqrt(sum |v_i - u(y_i) e|^2 / sum u(y_i)^2),
// velocity_max, velocity_max_reference. CSVs: poiseuille_error.csv (t, error at every
// output time), poiseuille_profile.csv (y, u, v, u_exact per particle).
std::unique_ptr<Analysis<2>> make_poiseuille_analysis(const YAML::Node& params, const Case& c);

}  // namespace curvsph
