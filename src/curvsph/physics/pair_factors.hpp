#pragma once
// Per-particle factors of the fluid pair sums, computed once per pass (O(n)) instead of once
// per pair (O(n x neighbours)): a division per pair costs about as much as the rest of the
// pair's arithmetic, and the phase -> viscosity lookup is two dependent loads. Each factor is
// the same expression the pair loop evaluated before, so the sums are bit-identical.
// The solver owns one PairFactors and reuses it every step (no allocation after the first).
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/physics/fluid_terms.hpp"

namespace curvsph {

template <int D>
struct PairFactors {
  std::vector<Real> volume;     // V_j = m_j / rho_j (continuity path, density gradient)
  std::vector<Real> inv_s2;     // 1 / sigma_j^2
  std::vector<Real> p_s2;       // p_j / sigma_j^2
  std::vector<Real> mu;         // dynamic viscosity of j's phase
  std::vector<Real> moment;     // renormalisation matrix accumulator, D(D+1)/2 per particle
  std::vector<Real> visc_coef;  // alpha h c0 rho0 / rho_j (artificial viscosity)

  void fill_volume(const Particles<D>& P) {
    volume.resize(P.size());
    parallel_for(static_cast<Index>(P.size()), [&](Index j) { volume[j] = P.mass[j] / P.rho[j]; });
  }

  void fill_forces(const Particles<D>& P, const FluidParams<D>& F) {
    inv_s2.resize(P.size());
    p_s2.resize(P.size());
    mu.resize(P.size());
    parallel_for(static_cast<Index>(P.size()), [&](Index j) {
      const Real s = P.sigma[j];
      inv_s2[j] = 1 / (s * s);
      p_s2[j] = P.p[j] * inv_s2[j];
      mu[j] = F.viscosity[P.phase[j]];
    });
  }

  std::size_t bytes() const {
    return (volume.capacity() + inv_s2.capacity() + p_s2.capacity() + mu.capacity() +
            moment.capacity() + visc_coef.capacity()) *
           sizeof(Real);
  }
};

}  // namespace curvsph
