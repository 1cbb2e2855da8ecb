#pragma once
// A liquid at rest under gravity (Calderon et al. §3.1, the 2-D hydrostatic tank; the initial
// state of the 3-D dam break, §3.2):
//   p(y) = rho0 g (y_s - y),  y_s = bottom + depth (the free surface),
// with g = |gravity| acting along -y (2-D) or -z (3-D, where y above reads z). Parameters (both for
// `analysis:` and `initial:`):
//   {depth: H, bottom: 0}   (bottom defaults to 0).
#include "curvsph/analysis/analysis.hpp"

namespace curvsph {

struct Hydrostatic {
  double depth = 0.5, bottom = 0, rho0 = 1000, g = 9.81;
  double surface() const { return bottom + depth; }
  double pressure(double y) const { return rho0 * g * (surface() - y); }
};

Hydrostatic hydrostatic_from_case(const Case& c, const YAML::Node& params, const std::string& key);

// Figures (2-D and 3-D; y is the last axis): kinetic_energy_max (max over output times of
// sum 1/2 m |u|^2 / (M g H)), kinetic_energy_final, pressure_l2_error (RMS of
// p - rho0 g (y_s - y) over the particles at the end, over rho0 g H), pressure_l2_error_deep
// (the same over the particles at least one support 2h below the surface: away from the free
// surface, whose particles miss part of their support), escaped_particles (at the wall or beyond it
// at the end), t_end_reached (t sqrt(g/H) at the end). Writes hydrostatic_history.csv (time,
// reduced time, reduced kinetic energy, reduced pressure error at every output time) and
// hydrostatic_profile.csv (y, p, p_exact of every particle at the end).
template <int D>
std::unique_ptr<Analysis<D>> make_hydrostatic_analysis(const YAML::Node& params, const Case& c);
// p from dp/dz = rho(p) g at depth z = y_s - y (the compressible balance with the EOS density,
// hydrostatic_analysis.cpp; 0 above the surface), rho from the EOS, mass = rho * the
// lattice volume (so sigma = rho/m keeps the lattice's number density; see
// taylor_green_initial), velocity 0. y is the last axis: y in 2-D, z in 3-D (gravity along -z).
template <int D>
void hydrostatic_initial(const Case& c, const YAML::Node& params, const Eos& eos,
                         const std::vector<Real>& rho0, Particles<D>& P);

}  // namespace curvsph
