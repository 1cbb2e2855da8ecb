#pragma once
// The two forms of the SPH pressure gradient (pressure_gradient: symmetric | difference).
//
// symmetric (Barker eq. 9, DESIGN.md §4; sigma = rho/m the number density):
//   m_i a_i = - sum_j (p_j/sigma_j^2 + p_i/sigma_i^2) grad_i W_ij
// conserves momentum pair by pair, but for a uniform pressure p it returns
//   - p R_i,  R_i = sum_j (1/sigma_j^2 + 1/sigma_i^2) grad_i W_ij,
// which vanishes only on an arrangement in discrete equilibrium (a lattice). On a disordered
// set R_i ~ e/h (e the first-moment error of the kernel sum), so the background pressure
// becomes a random force of order p e / (rho h): the -17..-32 % flux of the throttled pipe
// (throttled_pipe/findings.md §4) and the locked plug of Couette from rest
// (couette/findings.md §4).
//
// difference: subtract p_i R_i, i.e. the symmetric form less its own constant-field residual:
//   m_i a_i = - sum_j (p_j - p_i) / sigma_j^2 grad_i W_ij
// the zeroth-order consistent ("difference") SPH gradient sum_j V_j (A_j - A_i) grad_i W_ij
// (Monaghan 2005, Rep. Prog. Phys. 68: 1703, §2; here V_j = 1/sigma_j, m_i = rho_i/sigma_i),
// the form Sun, Colagrossi, Marrone & Zhang 2017 (delta+-SPH, CMAME 315) switch to where
// p_i < 0 (their tensile instability control; integrals_boundary.cpp item 2d).
// Any constant added to p cancels, whatever the arrangement; what remains of disorder is the
// first-moment error times h grad p, which vanishes with grad p. The price is pairwise
// momentum conservation (a pair's two forces sum to (p_i - p_j)(1/sigma_i^2 + 1/sigma_j^2)
// grad_i W_ij) and the ordering force of the background pressure: measured, the difference
// form alone clumps a summation-density particle set (throttled pipe, Couette from rest), so
// it is not the default (throttled_pipe/findings.md, last section).
//
// Walls take the same form: a ghost g of source s enters as a neighbour with (p_g - p_i), and
// the boundary integrals' wall term sum_b (p_b + p_i) W_ib n_b A_b becomes (p_b - p_i): both
// are the symmetric wall term less p_i times its share of R_i.
#include "curvsph/core/types.hpp"

namespace curvsph {

// The pressure part of one fluid pair's contribution for both particles, with g = grad_i W_ij
// = f r_ij: m_i a_i += pi, m_j a_j += pj. `s2i`, `s2j` are 1/sigma^2.
template <int D>
struct PairPressure {
  Vec<D> pi, pj;
};

template <int D>
inline PairPressure<D> pair_pressure(bool difference, Real p_i, Real p_j, Real s2i, Real s2j,
                                     const Vec<D>& g) {
  if (!difference) {
    const Vec<D> X = -(p_j * s2j + p_i * s2i) * g;
    return {X, -X};
  }
  // m_j a_j = -(p_i - p_j)/sigma_i^2 grad_j W_ji, grad_j W_ji = -g.
  return {Vec<D>(-(p_j - p_i) * s2j * g), Vec<D>((p_i - p_j) * s2i * g)};
}

}  // namespace curvsph
