#pragma once
// The force the fluid exerts on the walls from the fluid's momentum balance: every fluid pair
// term of the momentum equation is antisymmetric (m_i a_i^{(j)} = -m_j a_j^{(i)}: Barker's
// pressure and viscous sums with m_i / rho_i = 1 / sigma_i, the artificial viscosity), so the
// fluid's total rate of momentum sum_i m_i a_i is the body force plus the force the walls
// exert on it, and by Newton's third law
//   F_walls = -(sum_i m_i a_i - sum_i m_i g).
// In a periodic box with one wall this is the force on that wall, whatever the boundary
// treatment (ghosts, boundary integrals): a reference independent of how the wall terms are
// computed. `n`: the particles to sum (the owned ones).
#include "curvsph/core/particles.hpp"
#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
VecD<D> wall_force_from_momentum(const Particles<D>& P, Index n, const VecD<D>& gravity) {
  VecD<D> f = VecD<D>::Zero();
  for (Index i = 0; i < n; ++i) {
    const double m = static_cast<double>(P.mass[i]);
    f -= m * (P.a[i].template cast<double>() - gravity);
  }
  return f;
}

}  // namespace curvsph
