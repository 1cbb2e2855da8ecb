#pragma once
// Fluid-fluid pair terms of one force pass (DESIGN.md §4, Barker eqs. 9–11):
//   grad p_i / rho_i = (1/m_i) sum_j (p_j/sigma_j^2 + p_i/sigma_i^2) grad_i W_ij
//   mu lap u_i / rho_i = (mu/m_i) sum_j (1/sigma_j^2 + 1/sigma_i^2) (u_i - u_j) (1/r) dW/dr
// plus gravity and Vela Vela's driving term (eq. 36), and — on the continuity path — the
// density rate with delta-SPH (see density.hpp). Gather form: each particle sums over its
// own neighbours, so threads never write to the same particle.
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/physics/fluid_terms.hpp"

namespace curvsph {

template <int D>
void update_pressure(Particles<D>& P, const FluidParams<D>& F) {
  parallel_for(static_cast<Index>(P.size()), [&](Index i) {
    P.p[i] = F.eos.pressure(P.rho[i], F.rho0[P.phase[i]]);
    P.sigma[i] = P.rho[i] / P.mass[i];
  });
}

// Accelerations (and, when `continuity`, density rates) of every particle.
template <int D>
void fluid_forces(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                  const FluidParams<D>& F, bool continuity,
                  const std::vector<Vec<D>>* grad_rho) {
  const Real delta_term = F.delta_sph * W.h * F.eos.c0;
  parallel_for(static_cast<Index>(P.size()), [&](Index i) {
    const Real si = P.sigma[i];
    const Real pi_s2 = P.p[i] / (si * si);
    const Real inv_si2 = 1 / (si * si);
    const Real mu = F.viscosity[P.phase[i]];
    Vec<D> grad_p = Vec<D>::Zero();
    Vec<D> visc = Vec<D>::Zero();
    Real div = 0, diff = 0;
    cells.for_each_neighbor(P.x[i], P.x, [&](Index j, const Vec<D>& r, Real r2) {
      if (j == i) return;
      const Real f = W.gradient_factor(std::sqrt(r2));  // grad_i W_ij = r f
      const Real sj = P.sigma[j];
      const Real inv_sj2 = 1 / (sj * sj);
      grad_p += (P.p[j] * inv_sj2 + pi_s2) * f * r;
      const Vec<D> uij = P.v[i] - P.v[j];
      visc += (inv_sj2 + inv_si2) * f * uij;
      if (continuity) {
        const Real Vj = 1 / sj;
        div += Vj * f * uij.dot(r);
        if (delta_term > 0) {
          const Vec<D> psi = -2 * (P.rho[j] - P.rho[i]) * r / r2 -
                             ((*grad_rho)[i] + (*grad_rho)[j]);
          diff += Vj * f * psi.dot(r);
        }
      }
    });
    const Real inv_m = 1 / P.mass[i];
    Vec<D> a = -inv_m * grad_p + mu * inv_m * visc + F.gravity;
    if (F.drive) a[0] += (F.drive_v0 - P.v[i][0]) / F.drive_tau;
    P.a[i] = a;
    if (continuity) P.drho[i] = P.rho[i] * div + delta_term * diff;
  });
}

}  // namespace curvsph
