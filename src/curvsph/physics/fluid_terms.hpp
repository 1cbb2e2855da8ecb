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
  Real delta_sph = 0;  // Antuono et al. delta (continuity path only)
};

}  // namespace curvsph
