#pragma once
// Density by summation (Barker eq. 8: sigma_i = sum_j W_ij, rho_i = m_i sigma_i) and by the
// continuity equation with a delta-SPH diffusive term, by default Antuono et al.'s (2010, 2012;
// the other forms at DensityDiffusion):
//   drho_i/dt = rho_i sum_j V_j (u_i - u_j).grad_i W_ij
//             + delta h c0 sum_j V_j psi_ij.grad_i W_ij,
//   psi_ij = 2 (rho_j - rho_i) (x_j - x_i)/|x_ij|^2 - (<grad rho>^L_i + <grad rho>^L_j),
// where <grad rho>^L is the renormalised gradient (L_i = [sum_j V_j grad_i W_ij (x) (x_j -
// x_i)]^-1, exact for linear fields).
//
// Every pass here is symmetric: CellList::for_each_pair visits each pair once and its term is
// added to both particles, with the sign each term takes under i <-> j (r_ji = -r_ij,
// grad_j W_ji = -grad_i W_ij) written at the term. Neighbours come from the cell list's sorted
// copy of the positions: `cells` must have been built from P.x as it is now, which the solver
// guarantees (build_neighbors() right before the passes).
// [mpi] Every pass takes the pair rule of parallel/pair_rule.hpp (a plain `owned` count, or
// nothing, is the owner rule): it completes the sums of particles [0, rule.computed(P)); halo
// copies behind them are neighbours, or, under the midpoint rule, accumulate partial sums
// that rule.sum_halo() sends to their owners before anything reads the result.
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/parallel/pair_rule.hpp"
#include "curvsph/physics/pair_factors.hpp"

namespace curvsph {

// sigma_i = W(0) + sum_{j != i} W_ij: the pair term W_ij is the same for i and j.
template <int D>
void density_summation(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                       const PairRuleArg<D>& rule = {}) {
  const Index n = rule.computed(P);
  const Real w0 = W.value(0);  // the particle itself (its owner adds it, not a halo copy)
  parallel_for(rule.touched(P), [&](Index i) { P.sigma[i] = i < n ? w0 : 0; });
  rule.dispatch([&](auto midpoint) {
    constexpr bool M = decltype(midpoint)::value;
    cells.for_each_pair_acc(
        Real(0),
        [&](Real& sigma_i, Index i, Index j, const Vec<D>& r, Real r2) {
          if (!rule.template computes<M>(P, n, i, j, r)) return;
          const Real w = W.value(std::sqrt(r2));
          sigma_i += w;
          if (rule.template adds_to<M>(j, n)) P.sigma[j] += w;
        },
        [&](Index i, Real sigma_i) {
          if (rule.template adds_to<M>(i, n)) P.sigma[i] += sigma_i;
        });
  });
  rule.sum_halo(P.sigma);
  parallel_for(n, [&](Index i) { P.rho[i] = P.mass[i] * P.sigma[i]; });
}

// The renormalised density gradient <grad rho>^L_i of Antuono et al. (2012), into grad_rho:
//   <grad rho>^L_i = L_i g_i, g_i = sum_j V_j (rho_j - rho_i) grad_i W_ij,
//   L_i^-1 = M_i = sum_j V_j grad_i W_ij (x) (x_j - x_i) = -sum_j V_j f_ij r_ij r_ij^T
// (grad_i W_ij = f_ij r_ij, r_ij = x_i - x_j). Under i <-> j both pair terms keep their sign:
// f_ji r_ji r_ji^T = f_ij r_ij r_ij^T, and (rho_i - rho_j) f_ij r_ji = (rho_j - rho_i) f_ij r_ij;
// only the weight changes (V_j for i, V_i for j). M_i is symmetric: its D(D+1)/2 upper
// entries are accumulated in pf.moment (scratch: 24 bytes a particle in 2-D, 48 in 3-D), g_i
// in grad_rho itself.
// `pf` is the caller's reusable scratch (its volumes are filled here).
template <int D>
void renormalised_density_gradient(const Particles<D>& P, const CellList<D>& cells,
                                   const WendlandC2<D>& W, std::vector<Vec<D>>& grad_rho,
                                   PairFactors<D>& pf, const PairRuleArg<D>& rule = {}) {
  constexpr int K = D * (D + 1) / 2;
  const Index n = rule.computed(P);
  const Index touched = rule.touched(P);
  grad_rho.resize(P.size());
  pf.fill_volume(P);
  pf.moment.resize(static_cast<std::size_t>(touched) * K);
  const Real* V = pf.volume.data();
  Real* A = pf.moment.data();  // A_i = sum_j V_j f_ij r_ij r_ij^T = -M_i, upper triangle
  parallel_for(touched, [&](Index i) {
    grad_rho[i] = Vec<D>::Zero();
    for (int k = 0; k < K; ++k) A[i * K + k] = 0;
  });
  // Declared outside the generic lambda below: clang 14 (clang-tidy) crashes instantiating a
  // default member initialiser of a class local to a generic lambda.
  struct Sums {  // i's share of g_i and of the upper triangle of A_i
    Vec<D> g = Vec<D>::Zero();
    std::array<Real, K> a{};
  };
  rule.dispatch([&](auto midpoint) {
    constexpr bool M = decltype(midpoint)::value;
    cells.for_each_pair_acc(
        Sums{},
        [&](Sums& sum_i, Index i, Index j, const Vec<D>& r, Real r2) {
          if (!rule.template computes<M>(P, n, i, j, r)) return;
          const Vec<D> fr = r * W.gradient_factor(std::sqrt(r2));  // grad_i W_ij
          const Vec<D> g = (P.rho[j] - P.rho[i]) * fr;             // same for i and j
          std::array<Real, K> e;                                   // f r r^T, upper triangle
          int k = 0;
          for (int a = 0; a < D; ++a)
            for (int b = a; b < D; ++b) e[k++] = fr[a] * r[b];
          const Real Vj = V[j];
          sum_i.g += Vj * g;
          for (k = 0; k < K; ++k) sum_i.a[k] += Vj * e[k];
          if (rule.template adds_to<M>(j, n)) {
            const Real Vi = V[i];
            grad_rho[j] += Vi * g;
            for (k = 0; k < K; ++k) A[j * K + k] += Vi * e[k];
          }
        },
        [&](Index i, const Sums& sum_i) {
          if (!rule.template adds_to<M>(i, n)) return;
          grad_rho[i] += sum_i.g;
          for (int k = 0; k < K; ++k) A[i * K + k] += sum_i.a[k];
        });
  });
  rule.sum_halo(grad_rho);
  if (rule.halo) rule.halo->sum(A, K);
  parallel_for(n, [&](Index i) {
    Mat<D> M;
    int k = 0;
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b, ++k) M(a, b) = M(b, a) = -A[i * K + k];
    // An isolated particle (or a degenerate neighbourhood) keeps the plain gradient.
    const Real det = M.determinant();
    if (std::abs(det) > Real(1e-3)) grad_rho[i] = M.inverse() * grad_rho[i];
  });
}

template <int D>
void renormalised_density_gradient(const Particles<D>& P, const CellList<D>& cells,
                                   const WendlandC2<D>& W, std::vector<Vec<D>>& grad_rho) {
  PairFactors<D> pf;
  renormalised_density_gradient(P, cells, W, grad_rho, pf);
}

// The delta-SPH diffusive term's form (case key density.diffusion_term). The pair term is
//   delta h c0 V_j psi_ij.grad_i W_ij,  psi_ij.r_ij = -2 rho^T_ji - (<grad rho>_i + <grad
//   rho>_j).r_ij
// (r_ij = x_i - x_j; the second part only with the renormalised gradient), where
//   antuono:   rho^T_ji = rho_j - rho_i, with <grad rho>^L (Antuono et al. 2010, 2012): psi.r
//              vanishes for every linear field; it needs the gradient pass before this one;
//   molteni:   rho^T_ji = rho_j - rho_i, no gradient (Molteni & Colagrossi 2009): diffuses a
//              hydrostatic density profile too;
//   fourtakas: rho^T_ji = rho_j - rho_i - rho^H_ji, no gradient (Fourtakas, Dominguez, Vacondio
//              & Rogers 2019, Comput. Fluids 190: 346-361, the dynamic density): the part
//              rho^H_j - rho^H_i of a hydrostatic state is taken out, so that state is steady,
//              up to walls and the free surface, without the gradient pass. The linear EOS's
//              hydrostatic state has d rho/dz = -rho g / c0^2 (dp = c0^2 d rho = -rho g dz), so
//                rho^H_j - rho^H_i = rho_ij g.(x_j - x_i) / c0^2 = -rho_ij k.r_ij,
//              k = g / c0^2, rho_ij = (rho_i + rho_j)/2 (the trapezoid rule of the exponential
//              profile: exact to O(|k.r|^3)). The paper (and DualSPHysics) takes rho0 for
//              rho_ij, which keeps a profile of slope rho0 g / c0^2 steady instead: against
//              the momentum equation's rho g / c0^2, that mismatch set a steady pressure
//              error of 2.1 % of rho0 g H in the hydrostatic tank at t = 1 s (0.36 % with
//              rho_ij; Antuono 0.28 %). For Tait
//              the same form is first order (c^2 = c0^2 at rho0).
//              DualSPHysics offers the Molteni and Fourtakas terms (DensityDT 1 and 2), both
//              without a gradient pass.
template <int D>
struct DensityDiffusion {
  Real delta_h_c0 = 0;                  // delta h c0; 0: no diffusive term
  const Vec<D>* grad_rho = nullptr;     // antuono: <grad rho>^L of every particle
  Vec<D> hydrostatic = Vec<D>::Zero();  // fourtakas: k = g / c0^2; zero otherwise
};

// Density rate of the continuity equation with the delta-SPH term (above). Per pair, with
// f = f_ij (grad_i W_ij = f r_ij):
//   d = f (u_i - u_j).r_ij: under i <-> j, f (u_j - u_i).r_ji = d (symmetric);
//   q = delta h c0 f [-2 (rho_j - rho_i + rho_ij k.r_ij) - (<grad rho>_i + <grad rho>_j).r_ij]:
//       under i <-> j, f [-2 (rho_i - rho_j + rho_ij k.r_ji) - (<grad rho>_j + <grad rho>_i).r_ji]
//       = -q;
//   drho_i += V_j (rho_i d + q),  drho_j += V_i (rho_j d - q).
// `pf` is the caller's reusable scratch (its volumes are filled here).
template <int D>
void continuity_rate(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                     const DensityDiffusion<D>& diffusion, PairFactors<D>& pf,
                     const PairRuleArg<D>& rule = {}) {
  const Index n = rule.computed(P);
  pf.fill_volume(P);
  const Real* V = pf.volume.data();
  const Vec<D>* G = diffusion.grad_rho;
  const Real dhc = diffusion.delta_h_c0;
  const Vec<D> k = diffusion.hydrostatic;
  parallel_for(rule.touched(P), [&](Index i) { P.drho[i] = 0; });
  rule.dispatch([&](auto midpoint) {
    constexpr bool M = decltype(midpoint)::value;
    cells.for_each_pair_acc(
        Real(0),
        [&](Real& drho_i, Index i, Index j, const Vec<D>& r, Real r2) {
          if (!rule.template computes<M>(P, n, i, j, r)) return;
          const Real f = W.gradient_factor(std::sqrt(r2));
          const Real d = f * (P.v[i] - P.v[j]).dot(r);
          Real psi_r = -2 * (P.rho[j] - P.rho[i] + Real(0.5) * (P.rho[i] + P.rho[j]) * k.dot(r));
          if (G) psi_r -= (G[i] + G[j]).dot(r);
          const Real q = dhc * f * psi_r;
          drho_i += V[j] * (P.rho[i] * d + q);
          if (rule.template adds_to<M>(j, n)) P.drho[j] += V[i] * (P.rho[j] * d - q);
        },
        [&](Index i, Real drho_i) {
          if (rule.template adds_to<M>(i, n)) P.drho[i] += drho_i;
        });
  });
  rule.sum_halo(P.drho);
}

// The Antuono form: grad_rho is the renormalised gradient, or nullptr for the plain density
// difference (Molteni) or delta = 0.
template <int D>
void continuity_rate(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                     Real delta_h_c0, const std::vector<Vec<D>>* grad_rho, PairFactors<D>& pf,
                     const PairRuleArg<D>& rule = {}) {
  const DensityDiffusion<D> diffusion{delta_h_c0, grad_rho ? grad_rho->data() : nullptr,
                                      Vec<D>::Zero()};
  continuity_rate(P, cells, W, diffusion, pf, rule);
}

template <int D>
void continuity_rate(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                     Real delta_h_c0, const std::vector<Vec<D>>* grad_rho) {
  PairFactors<D> pf;
  continuity_rate(P, cells, W, delta_h_c0, grad_rho, pf);
}

}  // namespace curvsph
