#pragma once
// `analysis: {couette: {}}` and `initial: {couette: {}}`: circular Couette flow between two
// concentric circle walls (Barker & Neethling §2.1). The radii, the centre and the rotation
// rates come from the case's own `walls:` (a circle with fluid outside, one with fluid
// inside, each optionally `motion: {rotate: {omega, center}}` about the common centre), the
// density from fluid 0 — so `--set walls.0.motion.rotate.omega=0` changes the reference too.
#include "curvsph/analysis/analysis.hpp"
#include "curvsph/analysis/channel_flows.hpp"
#include "curvsph/kernels/wendland.hpp"

namespace curvsph {

struct CouetteSetup {
  CouetteFlow flow;
  Vec2d center = Vec2d::Zero();
};

// Reads the two circle walls of the case; `key` names the caller in messages.
CouetteSetup couette_from_case(const Case& c, const std::string& key);

// Figures:
//  density_error_t0   max |rho/rho0 - 1| over the fluid at t = 0;
//  density_error_end  the same at the end;
//  velocity_l2_error  Barker eq. 25 with the square, sqrt(mean (v_theta,i - v_theta(r_i))^2),
//                     divided by the largest wall speed (omega R_i), at the end; when no wall
//                     turns: velocity_rms = sqrt(mean |v_i|^2) instead (hydrostatic check);
//  velocity_l2_error_abs  eq. 25 itself (m/s), velocity_radial_rms;
//  velocity_profile_error, velocity_scatter_error  the split of velocity_l2_error into the
//                     error of the mean azimuthal profile (particles binned in radius, bins of
//                     about dx) and the particle scatter around it: l2^2 = profile^2 + scatter^2.
// CSVs: couette_error.csv (t, error at every output time), couette_density_t0.csv and
// couette_density_end.csv (r, rho/rho0 per particle), couette_profile.csv (r, v_theta, exact).
std::unique_ptr<Analysis<2>> make_couette_analysis(const YAML::Node& params, const Case& c);

// Node density sigma_ref,i = sum_j W_ij each particle would have without the walls, the mass
// calibration of couette_initial: when P holds exactly the generator's rings of the case's
// annulus, the sum runs over them and over the ring pattern continued beyond both walls
// (setup/generate.hpp), so near a wall only the wall treatment changes sigma; otherwise
// (relaxed particles) one value for all, the mean sigma of the particles whose support
// lies inside the fluid.
std::vector<double> reference_node_density(const Case& c, const CouetteSetup& s,
                                           const WendlandC2<2>& W, const Particles<2>& P);

// The steady profile as initial state: v = v_theta(r) e_theta, p = p0 + the radial balance
// (zero mean over the particles' volumes), rho = the EOS density of p, and mass
// m_i = rho_i / sigma_ref,i, so that the summation density rho_i = m_i sigma_i (Barker eq. 8)
// starts exactly at the balance wherever the walls do not reach.
void couette_initial(const Case& c, const YAML::Node& params, const Eos& eos,
                     const std::vector<Real>& rho0, Particles<2>& P);

}  // namespace curvsph
