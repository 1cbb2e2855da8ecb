#pragma once
// Fluid-fluid pair terms of one force pass (DESIGN.md §4, Barker eqs. 9–11):
//   grad p_i / rho_i = (1/m_i) sum_j (p_j/sigma_j^2 + p_i/sigma_i^2) grad_i W_ij
//   mu lap u_i / rho_i = (1/m_i) sum_j mu_ij (1/sigma_j^2 + 1/sigma_i^2) (u_i - u_j) (1/r) dW/dr
// with mu_ij = 2 mu_i mu_j / (mu_i + mu_j) between fluids of different viscosity (Hu & Adams
// 2006: keeps the pair force antisymmetric and the shear stress continuous at interfaces).
// Symmetric form: CellList::for_each_pair visits each pair once, its term goes to both
// particles (signs at fluid_forces). Neighbours come from the cell list's sorted copy of the
// positions: `cells` must have been built from P.x as it is now.
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/parallel/pair_rule.hpp"
#include "curvsph/physics/fluid_terms.hpp"
#include "curvsph/physics/pair_factors.hpp"
#include "curvsph/physics/pressure_gradient.hpp"

namespace curvsph {

template <int D>
void update_pressure(Particles<D>& P, const FluidParams<D>& F) {
  parallel_for(static_cast<Index>(P.size()), [&](Index i) {
    P.p[i] = F.eos.pressure(P.rho[i], F.rho0[P.phase[i]]);
    P.sigma[i] = P.rho[i] / P.mass[i];
  });
}

// Pair accelerations (pressure gradient and viscosity) of every particle; body forces are
// added by body_forces() after the wall terms. Per pair, with grad_i W_ij = f r_ij:
//   X_ij = -(p_j/sigma_j^2 + p_i/sigma_i^2) f r_ij + mu_ij (1/sigma_j^2 + 1/sigma_i^2) f (u_i -
//   u_j), m_i a_i += X_ij,  m_j a_j += X_ji = -X_ij
// (r_ji = -r_ij, u_j - u_i = -(u_i - u_j), the bracketed factors and the harmonic mean mu_ij
// are symmetric): pair forces are equal and opposite, momentum is conserved pair by pair.
// With `diff` (pressure_gradient: difference) the pressure part is pressure_gradient.hpp's
// -(p_j - p_i)/sigma_j^2 grad_i W_ij (zeroth-order consistent, not pairwise conservative).
// `pf` is the caller's reusable scratch (filled here); [mpi] `rule`: which pairs this rank
// computes and which particles it completes (parallel/pair_rule.hpp).
template <int D>
void fluid_forces(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                  const FluidParams<D>& F, PairFactors<D>& pf, const PairRuleArg<D>& rule = {},
                  bool diff = false) {
  const Index n = rule.computed(P);
  pf.fill_forces(P, F);
  const Real* inv_s2 = pf.inv_s2.data();
  const Real* p_s2 = pf.p_s2.data();
  const Real* mu = pf.mu.data();
  parallel_for(rule.touched(P), [&](Index i) { P.a[i] = Vec<D>::Zero(); });
  rule.dispatch([&](auto midpoint) {
    constexpr bool M = decltype(midpoint)::value;
    cells.for_each_pair_acc(
        Vec<D>(Vec<D>::Zero()),  // i's share of m_i a_i
        [&](Vec<D>& a_i, Index i, Index j, const Vec<D>& r, Real r2) {
          if (!rule.template computes<M>(P, n, i, j, r)) return;
          const Real f = W.gradient_factor(std::sqrt(r2));
          const Real mu_i = mu[i], mu_j = mu[j];
          const Real mu_ij = mu_i == mu_j ? mu_i : 2 * mu_i * mu_j / (mu_i + mu_j);
          if (diff) {  // pressure_gradient: difference (pressure_gradient.hpp)
            const Vec<D> V = f * mu_ij * (inv_s2[j] + inv_s2[i]) * (P.v[i] - P.v[j]);
            const Vec<D> g = f * r;
            const PairPressure<D> pp =
                pair_pressure<D>(true, P.p[i], P.p[j], inv_s2[i], inv_s2[j], g);
            a_i += V + pp.pi;
            if (rule.template adds_to<M>(j, n)) P.a[j] += pp.pj - V;
            return;
          }
          const Vec<D> X =
              f * (mu_ij * (inv_s2[j] + inv_s2[i]) * (P.v[i] - P.v[j]) - (p_s2[j] + p_s2[i]) * r);
          a_i += X;
          if (rule.template adds_to<M>(j, n)) P.a[j] -= X;
        },
        [&](Index i, const Vec<D>& a_i) {
          if (rule.template adds_to<M>(i, n)) P.a[i] += a_i;
        });
  });
  rule.sum_halo(P.a);
  parallel_for(n, [&](Index i) { P.a[i] *= 1 / P.mass[i]; });
}

// Convenience form with its own scratch (allocates: tests and one-off calls).
template <int D>
void fluid_forces(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                  const FluidParams<D>& F, bool difference = false) {
  PairFactors<D> pf;
  fluid_forces(P, cells, W, F, pf, {}, difference);
}

// Gravity and Vela Vela's driving term (eq. 36), added after the pair and wall terms.
template <int D>
void body_forces(Particles<D>& P, const FluidParams<D>& F) {
  parallel_for(static_cast<Index>(P.size()), [&](Index i) {
    P.a[i] += F.gravity;
    if (F.drive) P.a[i][0] += (F.drive_v0 - P.v[i][0]) / F.drive_tau;
  });
}

}  // namespace curvsph
