#pragma once
// Barker & Neethling §4.1, the throttled pipe: a channel periodic along x between two walls
// (any 2-D walls; the case uses NURBS curves) driven along x.
//
// Figures (analysis `throttled_pipe: {sections: 48, points: 65, midline_points: 192}`):
//  - flux_variation: (max - min)/mean of Q(x) = integral of v_x dy across the section
//    (Barker eq. 47) over `sections` (>= 20) equally spaced sections; v_x(x, y) is the SPH
//    interpolation of the fluid and its ghosts (the case's map and wall velocity, so the
//    velocity goes to the wall's at the wall), Shepard-normalised, integrated by Simpson's
//    rule with `points` nodes from wall to wall;
//  - flux_mean, reynolds = rho0 flux_mean / mu (the same at every section);
//  - midline_vy_max_rel: max |v_y| along the midline y_c(x) (half-way between the walls)
//    over max v_x there;
//  - centerline_vx_rel_error: relative L2 difference along the midline between v_x and
//    Barker eq. 48, v_x(x, y) = R(x0)/R(x) v_x(x0, y_c(x0) + (y - y_c(x)) R(x0)/R(x)), with
//    R the local half-gap measured between the walls and x0 the reference section at the
//    periodic seam (the wide end; Barker's x = 0); centerline_vx_max_rel_error its maximum
//    over max v_x;
//  - throat_vx_rel_error: the same comparison across the mid-length section (Fig. 9b);
//  - throat_half_width: R at mid-length, from the walls;
//  - with `reference_flux: Q_ref` (an independent steady flux of the same channel and
//    force, e.g. scripts/throttled_pipe_reference.py): reference_flux, reference_reynolds
//    and flux_rel_error = flux_mean / Q_ref - 1;
//  - flux_particles = sum V v_x / L_x over the particles (the mean over x of Q(x) with no
//    interpolation: the sections' kernel interpolation reads a parabolic profile low by ~1.5
//    sigma^2/R^2, h^2), and with a reference flux flux_particles_rel_error.
// CSV files (when the run writes files): throttled_pipe_flux.csv (x, R, y_c, Q),
// throttled_pipe_midline_x.csv (x, v_x, v_y, eq. 48, lubrication 3Q/(4R)),
// throttled_pipe_midline_y.csv (the mid-length section), throttled_pipe_history.csv
// (mean flux, flux variation and flux_particles at every output time).
#include <memory>
#include <vector>

#include "curvsph/analysis/analysis.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// The fluid interval [lo, hi] of the vertical line through x that contains y_start: where
// the signed distance to the nearest wall changes sign, marching by `step` (up to
// `reach` away from y_start) and bisecting to round-off. Throws std::runtime_error if a
// side has no wall within reach.
struct ChannelGap {
  double lo = 0, hi = 0;
  double half_width() const { return 0.5 * (hi - lo); }
  double center() const { return 0.5 * (hi + lo); }
};
ChannelGap channel_gap(const WallSet<2>& walls, double x, double y_start, double step,
                       double reach);

std::unique_ptr<Analysis<2>> make_throttled_pipe_analysis(const YAML::Node& params, const Case& c);

// Initial state `initial: {throttled_pipe: {velocity: rest | lubrication, flux: Q}}`: the particles
// of fluid 0 re-placed in wall-fitted columns, at rest (default) or with the lubrication
// flow of the body force (local Poiseuille profile 3Q/(4R)(1 - eta^2), eta = (y - y_c)/R,
// v_y along the streamlines y = y_c + eta R(x), Q = `flux` or by default the lubrication
// estimate 2 rho g_x L_x / (3 mu integral R^-3 dx))
// to skip most of the viscous spin-up (time scale 4 R^2 / (pi^2 nu) ~ 1 s). Column i sits at x_i =
// x_min + (i + 1/2) L_x/n_x with n_x = round(L_x/dx); between its walls (channel_gap) it holds n =
// round(gap/dx) particles at spacing dy = gap/n, the first and last dy/2 from the walls, with mass
// rho0 / n_lat, n_lat the node density of the column's lattice (L_x/n_x, dy) continued without
// end, so that the summation density starts at rho0 away from the walls. A lattice clipped by the
// curved walls leaves gaps of up to 1.5 dx along them (density deficits near 30 % at t = 0 that
// push particles through the wall within ~100 steps).
void throttled_pipe_initial(const Case& c, const YAML::Node& params, const Eos& eos,
                            const std::vector<Real>& rho0, Particles<2>& P);

}  // namespace curvsph
