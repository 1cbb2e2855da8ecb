// The symmetric pair passes (CellList::for_each_pair: each pair once, added to both
// particles) against a brute-force gather over all N^2 pairs written from the formulas of
// DESIGN.md §4 / Antuono et al. (2012): number density, renormalised density gradient,
// continuity rate with delta-SPH, pair forces with two viscosities. Periodic and open grids,
// 2-D and 3-D, and with the last particles marked as MPI halo copies (owned < N): owned
// particles still get every pair, halo entries are left untouched.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "../support/lattice.hpp"
#include "curvsph/physics/density.hpp"
#include "curvsph/physics/momentum.hpp"

namespace curvsph {
namespace {

template <int D>
struct Reference {
  std::vector<Real> sigma, drho;
  std::vector<Vec<D>> grad_rho, a;
};

// Brute force over every ordered pair (minimal image from the cell list's separation()).
template <int D>
Reference<D> brute_force(const Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                         const FluidParams<D>& F, Real dhc) {
  const std::size_t n = P.size();
  Reference<D> R;
  R.sigma.assign(n, 0);
  R.drho.assign(n, 0);
  R.grad_rho.assign(n, Vec<D>::Zero());
  R.a.assign(n, Vec<D>::Zero());
  auto V = [&](std::size_t j) { return P.mass[j] / P.rho[j]; };
  // Pass 1: sigma and the renormalised gradient (needed by the delta-SPH term of pass 2).
  for (std::size_t i = 0; i < n; ++i) {
    Mat<D> M = Mat<D>::Zero();
    Vec<D> g = Vec<D>::Zero();
    for (std::size_t j = 0; j < n; ++j) {
      const Vec<D> r = cells.separation(P.x[i], P.x[j]);
      const Real q = r.norm();
      if (q >= W.support) continue;
      R.sigma[i] += W.value(q);
      if (j == i) continue;
      const Vec<D> gradW = r * W.gradient_factor(q);
      M += V(j) * gradW * (-r).transpose();  // grad_i W_ij (x) (x_j - x_i)
      g += V(j) * (P.rho[j] - P.rho[i]) * gradW;
    }
    R.grad_rho[i] = std::abs(M.determinant()) > 1e-3 ? Vec<D>(M.inverse() * g) : g;
  }
  for (std::size_t i = 0; i < n; ++i) {
    Real div = 0, diff = 0;
    Vec<D> grad_p = Vec<D>::Zero(), visc = Vec<D>::Zero();
    const Real si2 = P.sigma[i] * P.sigma[i];
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const Vec<D> r = cells.separation(P.x[i], P.x[j]);
      const Real q = r.norm();
      if (q >= W.support) continue;
      const Vec<D> gradW = r * W.gradient_factor(q);
      div += V(j) * (P.v[i] - P.v[j]).dot(gradW);
      const Vec<D> psi =
          2 * (P.rho[j] - P.rho[i]) * (-r) / (q * q) - (R.grad_rho[i] + R.grad_rho[j]);
      diff += V(j) * psi.dot(gradW);
      const Real sj2 = P.sigma[j] * P.sigma[j];
      grad_p += (P.p[j] / sj2 + P.p[i] / si2) * gradW;
      const Real mi = F.viscosity[P.phase[i]], mj = F.viscosity[P.phase[j]];
      const Real mu = 2 * mi * mj / (mi + mj);
      visc += mu * (1 / sj2 + 1 / si2) * (P.v[i] - P.v[j]) * W.gradient_factor(q);
    }
    R.drho[i] = P.rho[i] * div + dhc * diff;
    R.a[i] = (visc - grad_p) / P.mass[i];
  }
  return R;
}

double rel(double a, double b, double scale) {
  return std::abs(a - b) / scale;
}

template <int D>
void check_against_brute_force(int n_side, bool periodic, bool halo) {
  test::Lattice<D> L(n_side, 1.5, 0.3, 5);
  auto& P = L.P;
  L.randomize_state(23, true);
  if (!periodic) {  // the same points on an open grid (bounding box cells, no images)
    L.cells.configure(L.W.support, Vec3d::Zero(), Vec3d::Ones(), {false, false, false});
    L.cells.build(P.x);
  }
  ASSERT_GE(L.cells.tile_count(), 3);  // several tiles
  FluidParams<D> F;
  F.rho0 = {1.0, 1.0};
  F.viscosity = {0.05, 0.2};  // mu_ij is the harmonic mean between the two phases
  F.eos.type = Eos::Type::linear;
  F.eos.c0 = 10;
  const Real dhc = 0.1 * L.W.h * F.eos.c0;
  const auto R = brute_force(P, L.cells, L.W, F, dhc);
  const auto N = static_cast<Index>(P.size());
  const Index owned = halo ? N - N / 3 : -1;
  const Index n = halo ? owned : N;
  // Halo entries must come out untouched: fill them with a sentinel.
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  Particles<D> Q = P;
  for (Index i = n; i < N; ++i) {
    Q.drho[i] = nan;
    Q.a[i] = Vec<D>::Constant(nan);
  }
  PairFactors<D> pf;
  std::vector<Vec<D>> grad(N, Vec<D>::Constant(nan));
  renormalised_density_gradient(Q, L.cells, L.W, grad, pf, owned);
  for (Index i = n; i < N; ++i) grad[i] = R.grad_rho[i];  // [mpi] update_halo's job
  continuity_rate(Q, L.cells, L.W, dhc, &grad, pf, owned);
  fluid_forces(Q, L.cells, L.W, F, pf, owned);
  // Scales: the largest magnitude of each field, so the tolerance is relative round-off.
  double sg = 0, sd = 0, sa = 0;
  for (Index i = 0; i < N; ++i) {
    sg = std::max(sg, R.grad_rho[i].norm());
    sd = std::max(sd, std::abs(R.drho[i]));
    sa = std::max(sa, R.a[i].norm());
  }
  double eg = 0, ed = 0, ea = 0;
  for (Index i = 0; i < n; ++i) {
    eg = std::max(eg, (grad[i] - R.grad_rho[i]).norm() / sg);
    ed = std::max(ed, rel(Q.drho[i], R.drho[i], sd));
    ea = std::max(ea, (Q.a[i] - R.a[i]).norm() / sa);
  }
  EXPECT_LT(eg, 1e-12);
  EXPECT_LT(ed, 1e-12);
  EXPECT_LT(ea, 1e-12);
  for (Index i = n; i < N; ++i) {
    EXPECT_TRUE(std::isnan(Q.drho[i]));
    EXPECT_TRUE(std::isnan(Q.a[i][0]));
  }
  // Number density last (it overwrites sigma and rho of the owned particles).
  for (Index i = n; i < N; ++i) Q.sigma[i] = nan;
  density_summation(Q, L.cells, L.W, owned);
  double es = 0, ss = 0;
  for (Index i = 0; i < N; ++i) ss = std::max(ss, R.sigma[i]);
  for (Index i = 0; i < n; ++i) {
    es = std::max(es, rel(Q.sigma[i], R.sigma[i], ss));
    EXPECT_EQ(Q.rho[i], Q.mass[i] * Q.sigma[i]);
  }
  EXPECT_LT(es, 1e-13);
  for (Index i = n; i < N; ++i) EXPECT_TRUE(std::isnan(Q.sigma[i]));
}

TEST(SymmetricPasses, MatchBruteForce2DPeriodic) {
  check_against_brute_force<2>(24, true, false);
}
TEST(SymmetricPasses, MatchBruteForce2DOpenWithHalo) {
  check_against_brute_force<2>(24, false, true);
}
TEST(SymmetricPasses, MatchBruteForce3DPeriodic) {
  check_against_brute_force<3>(14, true, false);
}
TEST(SymmetricPasses, MatchBruteForce3DPeriodicWithHalo) {
  check_against_brute_force<3>(14, true, true);
}
TEST(SymmetricPasses, MatchBruteForce3DOpen) {
  check_against_brute_force<3>(14, false, false);
}

}  // namespace
}  // namespace curvsph
