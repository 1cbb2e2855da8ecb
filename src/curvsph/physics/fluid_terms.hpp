#pragma once
// Per-particle constants the pair terms need, gathered once per run (not per pair).
#include <vector>

#include "curvsph/core/types.hpp"
#include "curvsph/physics/eos.hpp"

namespace curvsph {

template <int D>
struct FluidParams {
  std::vector<Real> rho0;       // per phase
  std::vector<Real> viscosity;  // dynamic, per phase
  Eos eos;
  Vec<D> gravity = Vec<D>::Zero();
  bool drive = false;  // Vela Vela eq. 36: dv/dt = (v0 - v_x)/tau x
  Real drive_v0 = 0, drive_tau = 1;
  Real delta_sph = 0;  // delta-SPH delta (continuity path only)
  // The diffusive term's form (physics/density.hpp, DensityDiffusion).
  enum class Diffusion { antuono, molteni, fourtakas } diffusion = Diffusion::antuono;
  // Fourtakas' k = g / c0^2 (rho^H_j - rho^H_i = -rho_ij k.r_ij, physics/density.hpp); zero
  // for the other forms.
  Vec<D> hydrostatic_density_gradient() const {
    if (diffusion != Diffusion::fourtakas) return Vec<D>::Zero();
    return gravity / (eos.c0 * eos.c0);
  }
};

}  // namespace curvsph
