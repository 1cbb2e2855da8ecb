#pragma once
// Particle shifting (Lind et al. 2012; in the form of Sun et al. 2017, delta+-SPH):
//   dr_i = -C (2h)^2 sum_j [1 + R (W_ij / W(dx))^n] grad_i W_ij V_j,   R = 0.2, n = 4,
// applied after each step and capped at a fraction of dx. Density and velocity follow the
// particle to its new place by a first-order Taylor step, phi_i += dr_i . grad phi_i
// (grad phi_i = sum_j V_j (phi_j - phi_i) grad_i W_ij); without that the shift itself writes
// acoustic noise into the fields. Without it, particles that meet at
// a hyperbolic stagnation point (Taylor–Green) line up in ever more anisotropic rows; the SPH
// divergence of a divergence-free field then drifts and the continuity density blows up.
//
// Walls. The fluid sum alone is one-sided next to a wall: it points into the fluid, so the
// shift -C (2h)^2 sum pushes every near-wall particle into the wall (the Couette annulus lost
// 164 particles through its walls in 6 steps that way). The solver therefore hands the sums
// to the boundary model between shift_sums() and apply_shift()
// (BoundaryModel::add_shift_sums): ghosts enter the shift direction as neighbours, boundary
// integrals subtract their wall sum sum_b W_ib n_b A_b (the continuum identity
// sum_j V_j grad W_ij ~ sum_b W_ib n_b A_b of integrals_boundary.cpp item 1), so the shift of
// a particle in a uniform arrangement next to a wall is ~0, as in the bulk; within dx of a
// wall the part towards it is dropped. The Taylor gradients stay the fluid's. A free surface
// has no such closure: shifting is for confined flows (it would push surface particles
// outwards).
//
// One symmetric pair pass (CellList::for_each_pair) accumulates the three sums. With
// grad_i W_ij = f r_ij (r_ij = x_i - x_j) and grad_j W_ji = -f r_ij, per pair:
//   s_i += c V_j f r,                s_j -= c V_i f r          (c = 1 + R (W_ij/W(dx))^n),
//   g_i += V_j (rho_j - rho_i) f r,  g_j += V_i (rho_j - rho_i) f r,
//   G_i += V_j (u_j - u_i) (f r)^T,  G_j += V_i (u_j - u_i) (f r)^T
// ((rho_i - rho_j)(-f r) = (rho_j - rho_i) f r; likewise for u).
#include <cmath>
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/parallel/pair_rule.hpp"

namespace curvsph {

// The sums of the shift pass, per particle (the solver's reusable scratch).
template <int D>
struct ShiftScratch {
  std::vector<Vec<D>> s, grad_rho;
  std::vector<Mat<D>> grad_v;  // grad_v(a, b) = d v_a / d x_b
  // Sun et al.'s anti-clumping R of the pair weight (0: the plain gradient of the kernel sum,
  // as the transport-velocity formulation takes it), and whether the Taylor gradients
  // grad_rho, grad_v are summed (only the shift carries fields along).
  Real anti_clumping = Real(0.2);
  bool taylor = true;
  std::size_t bytes() const {
    return (s.capacity() + grad_rho.capacity()) * sizeof(Vec<D>) +
           grad_v.capacity() * sizeof(Mat<D>);
  }
};

// Sun et al.'s anti-clumping weight c = 1 + R (W/W(dx))^n (R = 0.2, n = 4) of a pair at r.
template <int D>
inline Real shift_pair_weight(const WendlandC2<D>& W, Real r, Real w_dx, Real R = Real(0.2)) {
  if (R == 0) return 1;
  const Real ratio = W.value(r) / w_dx;
  const Real r4 = ratio * ratio * ratio * ratio;
  return 1 + R * r4;
}

// For a particle close to a wall of unit normal n (into the fluid): drops the part of the
// shift sum s that would move it towards the wall (the shift is -C (2h)^2 s, so that part is
// s.n > 0); the tangential part stays. Wall models call it for particles within dx of a
// wall, where neither the ghost at 2d nor the wall sum pushes back hard enough to stop a
// shift of up to 0.1 dx per step from carrying a particle across.
template <int D>
inline void shift_toward_wall_removed(Vec<D>& s, const Vec<D>& n) {
  const Real toward = s.dot(n);
  if (toward > 0) s -= toward * n;
}

// The fluid's sums of the shift for particles [0, rule.computed(P)), summed over the halo
// ([mpi] `rule`: which pairs this rank computes, parallel/pair_rule.hpp).
template <int D>
void shift_sums(const Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W, Real dx,
                ShiftScratch<D>& scratch, const PairRuleArg<D>& rule = {}) {
  const Index n = rule.computed(P);
  auto& S = scratch.s;
  auto& G = scratch.grad_rho;
  auto& Gv = scratch.grad_v;
  const bool taylor = scratch.taylor;
  const Real R = scratch.anti_clumping;
  S.resize(P.size());
  G.resize(taylor ? P.size() : 0);
  Gv.resize(taylor ? P.size() : 0);
  const Real w_dx = W.value(dx);
  parallel_for(rule.touched(P), [&](Index i) {
    S[i] = Vec<D>::Zero();
    if (!taylor) return;
    G[i] = Vec<D>::Zero();
    Gv[i] = Mat<D>::Zero();
  });
  rule.dispatch([&](auto midpoint) {
    constexpr bool M = decltype(midpoint)::value;
    cells.for_each_pair([&](Index i, Index j, const Vec<D>& r, Real r2) {
      if (!rule.template computes<M>(P, n, i, j, r)) return;
      const Real rr = std::sqrt(r2);
      const Vec<D> gradW = W.gradient_factor(rr) * r;  // grad_i W_ij
      const Real c = shift_pair_weight(W, rr, w_dx, R);
      const bool to_i = rule.template adds_to<M>(i, n), to_j = rule.template adds_to<M>(j, n);
      const Real Vj = P.mass[j] / P.rho[j], Vi = P.mass[i] / P.rho[i];
      if (to_i) S[i] += c * Vj * gradW;
      if (to_j) S[j] -= c * Vi * gradW;
      if (!taylor) return;
      const Vec<D> g = (P.rho[j] - P.rho[i]) * gradW;
      const Mat<D> gv = (P.v[j] - P.v[i]) * gradW.transpose();
      if (to_i) {
        G[i] += Vj * g;
        Gv[i].noalias() += Vj * gv;
      }
      if (to_j) {
        G[j] += Vi * g;
        Gv[j].noalias() += Vi * gv;
      }
    });
  });
  rule.sum_halo(S);
  if (!taylor) return;
  rule.sum_halo(G);
  rule.sum_halo(Gv);
}

// Moves particles [0, n) by -C (2h)^2 S (capped at 0.1 dx) and carries density and velocity
// along by the Taylor step.
template <int D>
void apply_shift(Particles<D>& P, Index n, const CellList<D>& cells, const WendlandC2<D>& W,
                 Real dx, Real coefficient, const ShiftScratch<D>& scratch) {
  const Real scale = coefficient * 4 * W.h * W.h;
  const Real cap = Real(0.1) * dx;
  parallel_for(n, [&](Index i) {
    Vec<D> d = -scale * scratch.s[i];
    const Real len = d.norm();
    if (len > cap) d *= cap / len;
    P.x[i] += d;
    cells.wrap(P.x[i]);
    P.rho[i] += scratch.grad_rho[i].dot(d);
    P.v[i] += scratch.grad_v[i] * d;
  });
}

// Shifts particles [0, rule.computed(P)) with the fluid's sums alone (no walls).
template <int D>
void shift_particles(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W, Real dx,
                     Real coefficient, ShiftScratch<D>& scratch, const PairRuleArg<D>& rule = {}) {
  shift_sums(P, cells, W, dx, scratch, rule);
  apply_shift(P, rule.computed(P), cells, W, dx, coefficient, scratch);
}

}  // namespace curvsph
