#pragma once
// The momentum diffusive term of the delta-SPH scheme (Antuono, Colagrossi, Marrone & Molteni
// 2010, CPC 181 eq. 3; analysed with the density diffusion in Antuono, Colagrossi & Marrone
// 2012, CPC 183, ref. [1] of Calderon et al., whose §3.1 runs "diffusive terms for both
// equations"): Monaghan's artificial viscosity without its quadratic part,
//   du_i/dt += alpha h c0 (rho0 / rho_i) sum_j pi_ij grad_i W_ij V_j,
//   pi_ij = (u_j - u_i).(x_j - x_i) / (|x_j - x_i|^2 + eta^2),   eta^2 = 0.01 h^2
// (eta keeps coincident particles finite, Monaghan 1992). It removes energy from approaching
// pairs only in proportion to their relative normal velocity, so it damps the particle-scale
// acoustic noise that the density diffusion alone leaves in the velocity field.
// Continuum limit (Taylor expansion of u_j - u_i under the sum, isotropic neighbourhood):
//   sum_j pi_ij grad_i W_ij V_j -> (lap u + 2 grad div u) / (2 (D + 2)),
// i.e. a shear viscosity nu = alpha h c0 / (2 (D + 2)) with a bulk part (Monaghan 2005 §6);
// the unit test checks this limit on a lattice.
// Near walls the sum is truncated like the fluid pressure sum; the boundary model's 1/gamma
// (boundary_model.hpp contract) renormalises it when this runs before add_accelerations().
// Ghost walls complete the sum instead: each ghost enters it as a neighbour with its no-slip
// velocity (ghost_boundary.cpp), so the term stays the Newtonian viscosity above up to the
// wall (tests/cases/test_couette_startup.cpp: a plane Couette start-up follows the series
// with nu + alpha h c0 / (2 (D + 2)); without the ghosts the wall rows slip, 0.27 U at 10 s).
//
// Form `approaching` (artificial_viscosity.form): Monaghan's artificial viscosity as he wrote
// it (Monaghan 1992, Annu. Rev. Astron. Astrophys. 30, eq. 4.1, without the beta mu^2 term),
//   du_i/dt = -sum_j m_j Pi_ij grad_i W_ij,
//   Pi_ij = -alpha h c mu_ij / rho_bar_ij  if u_ij.x_ij < 0, else 0,
//   mu_ij = u_ij.x_ij / (|x_ij|^2 + eta^2),  rho_bar_ij = (rho_i + rho_j) / 2,
// with u_ij = u_i - u_j, x_ij = x_i - x_j and c the solver's c0 (DualSPHysics' "artificial"
// viscosity, its usual setting for this dam break). It acts on approaching pairs only: a
// compression (an impact, the acoustic ringing after it) is damped, a stretching flow (the
// thin surge front) is not, which the all-pairs form above resists like a viscosity
// (docs/validation/dam_break_3d/findings.md: alpha 0.05 on all pairs delayed the impact by
// 0.019-0.046 s). Up to rho0 / rho_i V_j = m_j rho0 / (rho_i rho_j) against m_j / rho_bar
// (equal at rho = rho0) the pair factor is the all-pairs one, switched off for receding pairs.
#include <cmath>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/parallel/pair_rule.hpp"
#include "curvsph/physics/pair_factors.hpp"

namespace curvsph {

// artificial_viscosity.form (case_file.hpp)
enum class ArtificialViscosityForm { all_pairs, approaching };

// The `approaching` form's pair factor g_ij with du_i/dt += m_j g_ij x_ij and du_j/dt -=
// m_i g_ij x_ij (Monaghan 1992 eq. 4.1 with grad_i W_ij = f x_ij, f = W.gradient_factor(r)):
//   g_ij = -Pi_ij f = alpha h c0 mu_ij f / rho_bar_ij for u_ij.x_ij < 0, else 0.
// `ux` = u_ij.x_ij, `r2` = |x_ij|^2, `eta2` = 0.01 h^2.
inline Real monaghan_pair_factor(Real alpha_h_c0, Real rho_i, Real rho_j, Real f, Real ux, Real r2,
                                 Real eta2) {
  if (ux >= 0) return 0;
  return alpha_h_c0 * 2 / (rho_i + rho_j) * f * ux / (r2 + eta2);
}

// Adds the term to P.a (after the fluid pair forces); nothing when alpha_h_c0 = alpha h c0 is
// 0 (the default: off). `rho0` per phase; [mpi] `rule`: which pairs this rank computes and
// which particles it completes (parallel/pair_rule.hpp). Neighbours through the cell list's sorted
// copy of the positions: `cells` must have been built from P.x as it is.
// `pf` is the caller's reusable scratch: the per-particle factors (V_k = m_k / rho_k and the
// coefficient alpha h c0 rho0 / rho_k) are computed once per particle, not per pair (the
// per-pair divisions and the store to i at every pair made this pass cost ~3/4 of a whole
// dam-break step).
template <int D>
void add_artificial_viscosity(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                              Real alpha_h_c0, const std::vector<Real>& rho0, PairFactors<D>& pf,
                              const PairRuleArg<D>& rule = {},
                              ArtificialViscosityForm form = ArtificialViscosityForm::all_pairs) {
  if (alpha_h_c0 == 0) return;
  const bool approaching = form == ArtificialViscosityForm::approaching;
  const Index n = rule.computed(P);
  // Under the midpoint rule the halo copies' entries of P.a are zero here (the force pass
  // sent them to their owners): they collect this pass's part alone.
  const Real eta2 = Real(0.01) * W.h * W.h;
  pf.fill_volume(P);
  pf.visc_coef.resize(P.size());
  parallel_for(static_cast<Index>(P.size()), [&](Index k) {
    pf.visc_coef[k] = alpha_h_c0 * rho0[static_cast<std::size_t>(P.phase[k])] / P.rho[k];
  });
  const Real* V = pf.volume.data();
  const Real* C = pf.visc_coef.data();
  // Each pair once (CellList::for_each_pair_acc): with r = x_i - x_j and grad_i W_ij = f r,
  // pi_ji = pi_ij and grad_j W_ji = -f r, so j receives the same pair factor with the
  // opposite sign, weighted by its own coefficient and i's volume.
  rule.dispatch([&](auto midpoint) {
    constexpr bool M = decltype(midpoint)::value;
    cells.for_each_pair_acc(
        Vec<D>(Vec<D>::Zero()),
        [&](Vec<D>& a_i, Index i, Index j, const Vec<D>& r, Real r2) {
          if (!rule.template computes<M>(P, n, i, j, r)) return;
          if (approaching) {
            const Real g = monaghan_pair_factor(alpha_h_c0, P.rho[i], P.rho[j],
                                                W.gradient_factor(std::sqrt(r2)),
                                                (P.v[i] - P.v[j]).dot(r), r2, eta2);
            if (g == 0) return;
            a_i += (g * P.mass[j]) * r;
            if (rule.template adds_to<M>(j, n)) P.a[j] -= (g * P.mass[i]) * r;
            return;
          }
          // (u_j - u_i).(x_j - x_i) = (u_i - u_j).r
          const Real f = W.gradient_factor(std::sqrt(r2)) * (P.v[i] - P.v[j]).dot(r) / (r2 + eta2);
          a_i += (C[i] * f * V[j]) * r;
          if (rule.template adds_to<M>(j, n)) P.a[j] -= (C[j] * f * V[i]) * r;
        },
        [&](Index i, const Vec<D>& a_i) {
          if (rule.template adds_to<M>(i, n)) P.a[i] += a_i;
        });
  });
  rule.sum_halo(P.a);
}

template <int D>
void add_artificial_viscosity(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                              Real alpha_h_c0, const std::vector<Real>& rho0,
                              ArtificialViscosityForm form = ArtificialViscosityForm::all_pairs) {
  PairFactors<D> pf;
  add_artificial_viscosity(P, cells, W, alpha_h_c0, rho0, pf, {}, form);
}

}  // namespace curvsph
