#pragma once
// Density by summation (Barker eq. 8: sigma_i = sum_j W_ij, rho_i = m_i sigma_i) and by the
// continuity equation with the delta-SPH diffusive term of Antuono et al. (2010, 2012):
//   drho_i/dt = rho_i sum_j V_j (u_i - u_j).grad_i W_ij
//             + delta h c0 sum_j V_j psi_ij.grad_i W_ij,
//   psi_ij = 2 (rho_j - rho_i) (x_j - x_i)/|x_ij|^2 - (<grad rho>^L_i + <grad rho>^L_j),
// where <grad rho>^L is the renormalised gradient (L_i = [sum_j V_j grad_i W_ij (x) (x_j -
// x_i)]^-1, exact for linear fields).
// Every pass here reads neighbours through the cell list's own sorted copy of the positions
// (CellList::for_each_neighbor without a position array): `cells` must have been built from
// P.x as it is now, which the solver guarantees (build_neighbors() right before the passes).
#include <Eigen/LU>
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/physics/pair_factors.hpp"

namespace curvsph {

// `owned`: the particles computed (computed_count; -1: all).
template <int D>
void density_summation(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                       Index owned = -1) {
  parallel_for(computed_count(P, owned), [&](Index i) {
    Real s = 0;
    cells.for_each_neighbor(P.x[i],
                            [&](Index, const Vec<D>&, Real r2) { s += W.value(std::sqrt(r2)); });
    P.sigma[i] = s;
    P.rho[i] = P.mass[i] * s;
  });
}

// The renormalised density gradient <grad rho>^L_i of Antuono et al. (2012), into grad_rho.
// `pf` is the caller's reusable scratch (its volumes are filled here); `owned`: the particles
// computed (computed_count; -1: all).
template <int D>
void renormalised_density_gradient(const Particles<D>& P, const CellList<D>& cells,
                                   const WendlandC2<D>& W, std::vector<Vec<D>>& grad_rho,
                                   PairFactors<D>& pf, Index owned = -1) {
  grad_rho.resize(P.size());
  pf.fill_volume(P);
  const Real* V = pf.volume.data();
  parallel_for(computed_count(P, owned), [&](Index i) {
    Mat<D> M = Mat<D>::Zero();
    Vec<D> g = Vec<D>::Zero();
    cells.for_each_neighbor(P.x[i], [&](Index j, const Vec<D>& r, Real r2) {
      if (j == i) return;
      const Vec<D> gradW = r * W.gradient_factor(std::sqrt(r2));  // grad_i W_ij
      const Real Vj = V[j];
      M.noalias() -= Vj * gradW * r.transpose();  // grad W (x) (x_j - x_i), x_j - x_i = -r
      g += Vj * (P.rho[j] - P.rho[i]) * gradW;
    });
    // An isolated particle (or a degenerate neighbourhood) keeps the plain gradient.
    const Real det = M.determinant();
    grad_rho[i] = std::abs(det) > Real(1e-3) ? Vec<D>(M.inverse() * g) : g;
  });
}

template <int D>
void renormalised_density_gradient(const Particles<D>& P, const CellList<D>& cells,
                                   const WendlandC2<D>& W, std::vector<Vec<D>>& grad_rho) {
  PairFactors<D> pf;
  renormalised_density_gradient(P, cells, W, grad_rho, pf);
}

// Density rate of the continuity equation with the delta-SPH term (header comment); grad_rho
// is the renormalised gradient, or nullptr when delta = 0. `pf` is the caller's reusable
// scratch (its volumes are filled here); `owned`: the particles computed (computed_count;
// -1: all).
template <int D>
void continuity_rate(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                     Real delta_h_c0, const std::vector<Vec<D>>* grad_rho, PairFactors<D>& pf,
                     Index owned = -1) {
  pf.fill_volume(P);
  const Real* V = pf.volume.data();
  parallel_for(computed_count(P, owned), [&](Index i) {
    Real div = 0, diff = 0;
    cells.for_each_neighbor(P.x[i], [&](Index j, const Vec<D>& r, Real r2) {
      if (j == i) return;
      const Real f = W.gradient_factor(std::sqrt(r2));  // grad_i W_ij = r f
      const Real Vj = V[j];
      div += Vj * f * (P.v[i] - P.v[j]).dot(r);
      if (grad_rho) {
        const Vec<D> psi = -2 * (P.rho[j] - P.rho[i]) * r / r2 - ((*grad_rho)[i] + (*grad_rho)[j]);
        diff += Vj * f * psi.dot(r);
      }
    });
    P.drho[i] = P.rho[i] * div + delta_h_c0 * diff;
  });
}

template <int D>
void continuity_rate(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                     Real delta_h_c0, const std::vector<Vec<D>>* grad_rho) {
  PairFactors<D> pf;
  continuity_rate(P, cells, W, delta_h_c0, grad_rho, pf);
}

}  // namespace curvsph
