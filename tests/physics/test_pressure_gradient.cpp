// The two pressure-gradient forms (physics/pressure_gradient.hpp) through fluid_forces.
// References: the exact gradient of a uniform field (zero) and of a linear field (-G/rho),
// and the symmetric form's constant-field residual summed by brute force.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/lattice.hpp"
#include "curvsph/physics/density.hpp"
#include "curvsph/physics/momentum.hpp"

namespace curvsph {
namespace {

using test::Lattice;

template <int D>
FluidParams<D> inviscid() {
  FluidParams<D> F;
  F.rho0 = {1.0};
  F.viscosity = {0.0};
  F.eos.type = Eos::Type::linear;
  F.eos.c0 = 10;
  return F;
}

// Pressure accelerations on a jittered periodic lattice with p_i = p(x_i).
template <int D, class Field>
std::vector<Vec<D>> accelerations(Lattice<D>& L, bool difference, Field p) {
  auto& P = L.P;
  density_summation(P, L.cells, L.W);
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.sigma[i] = P.rho[i] / P.mass[i];
    P.p[i] = p(P.x[i]);
    P.v[i].setZero();
  }
  fluid_forces(P, L.cells, L.W, inviscid<D>(), difference);
  return P.a;
}

// A uniform pressure on a disordered set: the symmetric form returns -p R_i / m_i, R_i its
// constant-field residual (summed here by brute force over every particle); the difference
// form returns exactly nothing.
template <int D>
void check_uniform_pressure() {
  Lattice<D> L(D == 2 ? 24 : 10, 1.3, 0.2, 5);
  const Real p0 = 250;
  const auto sym = accelerations(L, false, [&](const Vec<D>&) { return p0; });
  const auto& P = L.P;
  double largest = 0;
  for (Index i : {Index(0), Index(37), static_cast<Index>(P.size() / 2)}) {
    Vec<D> R = Vec<D>::Zero();
    for (std::size_t j = 0; j < P.size(); ++j) {
      if (static_cast<Index>(j) == i) continue;
      const Vec<D> r = L.cells.separation(P.x[i], P.x[j]);
      const Real rr = r.norm();
      if (!(rr < L.W.support)) continue;
      R += (1 / (P.sigma[j] * P.sigma[j]) + 1 / (P.sigma[i] * P.sigma[i])) *
           L.W.gradient_factor(rr) * r;
    }
    const Vec<D> ref = -p0 * R / P.mass[i];
    EXPECT_LT((sym[i] - ref).norm(), 1e-9 * ref.norm() + 1e-12) << "particle " << i;
    largest = std::max(largest, static_cast<double>(ref.norm()));
  }
  // The residual is far from zero on the jittered set: p0 / (rho dx) times a few per cent.
  EXPECT_GT(largest, 1e-3 * p0 / L.dx);
  const auto dif = accelerations(L, true, [&](const Vec<D>&) { return p0; });
  for (std::size_t i = 0; i < P.size(); ++i) ASSERT_EQ(dif[i].norm(), 0.0) << "particle " << i;
}

TEST(PressureGradient, UniformPressureExertsNoForceInTheDifferenceForm2D) {
  check_uniform_pressure<2>();
}
TEST(PressureGradient, UniformPressureExertsNoForceInTheDifferenceForm3D) {
  check_uniform_pressure<3>();
}

// p = p0 + G.x away from the periodic seam: the difference form's error does not depend on
// p0 (to round-off) and is a fraction of |G|/rho set by the disorder; the symmetric form's
// grows with p0.
TEST(PressureGradient, LinearPressureErrorIndependentOfBackground) {
  Lattice<2> L(40, 1.3, 0.15, 9);
  const Vec<2> G(30, -20);
  auto err = [&](bool difference, Real p0) {
    const auto a = accelerations(L, difference, [&](const Vec<2>& x) { return p0 + G.dot(x); });
    double e = 0;
    int n = 0;
    for (std::size_t i = 0; i < L.P.size(); ++i) {
      if (!L.interior(static_cast<Index>(i), 2 * L.W.support)) continue;
      e += (a[i] + G / L.P.rho[i]).squaredNorm();
      ++n;
    }
    return std::sqrt(e / n) / G.norm();
  };
  const double d0 = err(true, 0), d1 = err(true, 1e4);
  EXPECT_LT(d0, 0.2);
  EXPECT_NEAR(d1, d0, 1e-6 * d0);
  const double s1 = err(false, 1e4);
  EXPECT_GT(s1, 20 * d1);
}

}  // namespace
}  // namespace curvsph
