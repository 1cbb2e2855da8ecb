#pragma once
// Transport-velocity formulation (Adami, Hu & Adams 2013, JCP 241: 292-307; "TVF").
//
// Why: in a confined, slow flow the equation of state needs a background pressure to keep the
// particles from clumping, but the pressure sum sees that background through the
// kernel-gradient error of the disordered particle set (a first-moment error e/h times p),
// a random force that acts as a drag (throttled pipe: findings.md §4, -32 % flux at p ~ 21 Pa,
// -17 % with the background removed). The TVF moves the background pressure out of the
// momentum equation: particles are carried by a transport velocity
//   u~_i = u_i + (dt/2) b_i,   b_i = -(p_b / m_i) sum_j (V_i^2 + V_j^2) grad_i W_ij
// (Adami et al. eq. 13 with the integrator of their §3.4), which pushes them towards a uniform
// arrangement with a background pressure p_b that never enters the momentum equation; the
// momentum equation gains the divergence of A = rho u (u~ - u) (eq. 8 and 15):
//   a_i += (1/m_i) sum_j (V_i^2 + V_j^2) (1/2) (A_i + A_j) . grad_i W_ij.
// The eos then only needs p0 ~ 0 (p = B((rho/rho0)^gamma - 1)).
//
// b is taken with equal volumes, (V_i^2 + V_j^2)/m_i -> 2 V_j / rho_i: b_i = -(2 p_b / rho_i) S_i,
// S_i = sum_j V_j grad_i W_ij, the gradient of the kernel sum. That is the sum particle
// shifting builds (particle_shifting.hpp, here without the anti-clumping weight), so the
// boundary models close it at the walls the same way (ghosts as neighbours, boundary
// integrals their wall sum), and a particle within dx of a wall is not pulled towards it.
// The walls' share of A is zero (Adami et al.: u~ = u at a wall).
//
// Integration (Solver::step, kick-drift-kick): v^{n+1/2} = v^n + dt/2 a^n,
// x^{n+1} = x^n + dt (v^{n+1/2} + dt/2 b^n); the forces at n+1 use du = u~ - u = dt/2 b^n in A.
// Summation density only (the density follows the positions); confined flows only (a free
// surface has no background pressure to balance p_b: its particles would be pushed out).
#include <cmath>
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/parallel/pair_rule.hpp"
#include "curvsph/physics/particle_shifting.hpp"

namespace curvsph {

template <int D>
struct TransportVelocity {
  Real background_pressure = 0;  // p_b (Pa); 0: off
  ShiftScratch<D> sums;          // S_i: no anti-clumping weight, no Taylor gradients
  std::vector<Vec<D>> b;         // background-pressure acceleration of the last force evaluation
  std::vector<Vec<D>> du;        // u~ - u of the current drift, dt/2 b

  TransportVelocity() {
    sums.anti_clumping = 0;
    sums.taylor = false;
  }
  bool enabled() const { return background_pressure > 0; }
  std::size_t bytes() const {
    return sums.bytes() + (b.capacity() + du.capacity()) * sizeof(Vec<D>);
  }
};

// b_i = -(2 p_b / rho_i) S_i for particles [0, n), from the (wall-closed) sums.
template <int D>
void transport_acceleration(const Particles<D>& P, Index n, TransportVelocity<D>& tv) {
  tv.b.resize(P.size(), Vec<D>::Zero());
  const Real two_pb = 2 * tv.background_pressure;
  parallel_for(n, [&](Index i) { tv.b[i] = -(two_pb / P.rho[i]) * tv.sums.s[i]; });
}

// The momentum equation's divergence of A = rho u (u~ - u) over fluid pairs (tv.du must hold
// u~ - u of every particle the pass reads, halo included), added to P.a of [0, rule.computed).
// Per pair, with grad_i W_ij = f r_ij and (A . g) = rho u (du . g):
//   X_ij = (V_i^2 + V_j^2) (1/2) (A_i + A_j) . grad_i W_ij,  m_i a_i += X_ij,  m_j a_j -= X_ij.
template <int D>
void add_transport_stress(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                          const TransportVelocity<D>& tv, std::vector<Vec<D>>& acc,
                          const PairRuleArg<D>& rule = {}) {
  const Index n = rule.computed(P);
  acc.resize(P.size());
  parallel_for(rule.touched(P), [&](Index i) { acc[i] = Vec<D>::Zero(); });
  const auto& du = tv.du;
  rule.dispatch([&](auto midpoint) {
    constexpr bool M = decltype(midpoint)::value;
    cells.for_each_pair([&](Index i, Index j, const Vec<D>& r, Real r2) {
      if (!rule.template computes<M>(P, n, i, j, r)) return;
      const Vec<D> g = W.gradient_factor(std::sqrt(r2)) * r;
      const Real Vi = P.mass[i] / P.rho[i], Vj = P.mass[j] / P.rho[j];
      const Vec<D> X = (Real(0.5) * (Vi * Vi + Vj * Vj)) *
                       (P.rho[i] * du[i].dot(g) * P.v[i] + P.rho[j] * du[j].dot(g) * P.v[j]);
      if (rule.template adds_to<M>(i, n)) acc[i] += X;
      if (rule.template adds_to<M>(j, n)) acc[j] -= X;
    });
  });
  rule.sum_halo(acc);
  parallel_for(n, [&](Index i) { P.a[i] += acc[i] / P.mass[i]; });
}

}  // namespace curvsph
