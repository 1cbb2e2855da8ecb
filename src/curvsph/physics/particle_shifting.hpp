#pragma once
// Particle shifting (Lind et al. 2012; in the form of Sun et al. 2017, delta+-SPH):
//   dr_i = -C (2h)^2 sum_j [1 + R (W_ij / W(dx))^n] grad_i W_ij V_j,   R = 0.2, n = 4,
// applied after each step and capped at a fraction of dx. Density and velocity follow the
// particle to its new place by a first-order Taylor step, phi_i += dr_i . grad phi_i
// (grad phi_i = sum_j V_j (phi_j - phi_i) grad_i W_ij); without that the shift itself writes
// acoustic noise into the fields. Without it, particles that meet at
// a hyperbolic stagnation point (Taylor–Green) line up in ever more anisotropic rows; the SPH
// divergence of a divergence-free field then drifts and the continuity density blows up.
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph {

template <int D>
void shift_particles(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W, Real dx,
                     Real coefficient, std::vector<Vec<D>>& shift, std::vector<Real>& drho,
                     std::vector<Vec<D>>& dv, Index owned = -1) {
  // `owned`: the particles shifted (computed_count; -1: all).
  const Index n = computed_count(P, owned);
  shift.resize(P.size());
  drho.resize(P.size());
  dv.resize(P.size());
  const Real w_dx = W.value(dx);
  const Real scale = coefficient * 4 * W.h * W.h;
  const Real cap = Real(0.1) * dx;
  parallel_for(n, [&](Index i) {
    Vec<D> s = Vec<D>::Zero();
    Vec<D> grad_rho = Vec<D>::Zero();
    Mat<D> grad_v = Mat<D>::Zero();  // grad_v(a, b) = d v_a / d x_b
    cells.for_each_neighbor(P.x[i], P.x, [&](Index j, const Vec<D>& r, Real r2) {
      if (j == i) return;
      const Real rr = std::sqrt(r2);
      const Real ratio = W.value(rr) / w_dx;
      const Real r4 = ratio * ratio * ratio * ratio;
      const Vec<D> gradW = W.gradient_factor(rr) * r;
      const Real Vj = P.mass[j] / P.rho[j];
      s += (1 + Real(0.2) * r4) * Vj * gradW;
      grad_rho += Vj * (P.rho[j] - P.rho[i]) * gradW;
      grad_v.noalias() += Vj * (P.v[j] - P.v[i]) * gradW.transpose();
    });
    Vec<D> d = -scale * s;
    const Real len = d.norm();
    if (len > cap) d *= cap / len;
    shift[i] = d;
    drho[i] = grad_rho.dot(d);
    dv[i] = grad_v * d;
  });
  parallel_for(n, [&](Index i) {
    P.x[i] += shift[i];
    cells.wrap(P.x[i]);
    P.rho[i] += drho[i];
    P.v[i] += dv[i];
  });
}

}  // namespace curvsph
