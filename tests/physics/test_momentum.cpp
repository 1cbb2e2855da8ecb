// Momentum equation pair terms (DESIGN.md §4): pressure and viscous forces are antisymmetric
// (linear momentum conserved to round-off), uniform pressure on a perfect lattice and a
// uniform velocity field exert no force, and whole solver steps keep mass and momentum.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <random>
#include <vector>

#include "../support/lattice.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/physics/density.hpp"
#include "curvsph/physics/momentum.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

using test::Lattice;

template <int D>
const std::vector<Vec<D>>* no_gradient() {
  return nullptr;  // no renormalised density gradient (delta-SPH off)
}

template <int D>
FluidParams<D> params(double viscosity, double delta_sph = 0) {
  FluidParams<D> F;
  F.rho0 = {1.0};
  F.viscosity = {viscosity};
  F.eos.type = Eos::Type::linear;
  F.eos.c0 = 10;
  F.delta_sph = delta_sph;
  return F;  // gravity zero, driving term off
}

// The solver's pair passes: accelerations, and on the continuity path the density rate.
template <int D, class Lat>
void pair_terms(Particles<D>& P, const Lat& L, const FluidParams<D>& F, bool continuity,
                const std::vector<Vec<D>>* grad_rho) {
  fluid_forces(P, L.cells, L.W, F);
  if (continuity) continuity_rate(P, L.cells, L.W, F.delta_sph * L.W.h * F.eos.c0, grad_rho);
}

// Random velocities, pressures (of both signs), masses and densities on a jittered periodic
// lattice; returns |sum_i m_i a_i| / sum_i |m_i a_i| and the same for the density rate's mass
// flux sum_i V_i drho_i (continuity path).
template <int D>
void check_pair_forces_cancel(bool continuity) {
  Lattice<D> L(D == 2 ? 24 : 10, 1.3, 0.3, 3);
  auto& P = L.P;
  L.randomize_state(17);
  const auto F = params<D>(0.05, continuity ? 0.1 : 0);
  std::vector<Vec<D>> grad_rho;
  if (continuity) renormalised_density_gradient(P, L.cells, L.W, grad_rho);
  pair_terms(P, L, F, continuity, continuity ? &grad_rho : nullptr);
  Vec<D> total = Vec<D>::Zero();
  double scale = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    total += P.mass[i] * P.a[i];
    scale += P.mass[i] * P.a[i].norm();
  }
  ASSERT_GT(scale, 0);
  EXPECT_LT(total.norm(), 1e-12 * scale) << "sum m a = " << total.transpose();

  // Pressure alone and viscosity alone cancel separately too.
  for (int part = 0; part < 2; ++part) {
    Particles<D> Q = P;
    auto G = F;
    if (part == 0) G.viscosity = {0.0};
    if (part == 1)
      for (auto& p : Q.p) p = 0;
    pair_terms(Q, L, G, continuity, continuity ? &grad_rho : nullptr);
    Vec<D> t = Vec<D>::Zero();
    double s = 0;
    for (std::size_t i = 0; i < Q.size(); ++i) {
      t += Q.mass[i] * Q.a[i];
      s += Q.mass[i] * Q.a[i].norm();
    }
    ASSERT_GT(s, 0);
    EXPECT_LT(t.norm(), 1e-12 * s) << (part == 0 ? "pressure" : "viscosity");
  }
}

TEST(Momentum, PairForcesSumToZero2D) {
  check_pair_forces_cancel<2>(false);
}
TEST(Momentum, PairForcesSumToZero3D) {
  check_pair_forces_cancel<3>(false);
}
TEST(Momentum, PairForcesSumToZeroContinuity2D) {
  check_pair_forces_cancel<2>(true);
}
TEST(Momentum, PairForcesSumToZeroContinuity3D) {
  check_pair_forces_cancel<3>(true);
}

template <int D>
void check_uniform_pressure_on_lattice() {
  Lattice<D> L(D == 2 ? 20 : 10, 1.3, 0);
  auto& P = L.P;
  density_summation(P, L.cells, L.W);  // uniform on a perfect periodic lattice
  for (auto& p : P.p) p = 250;
  const auto F = params<D>(0.1);
  pair_terms(P, L, F, false, no_gradient<D>());
  // Scale: one neighbour's share of the pressure force per unit mass.
  const double s = P.sigma[0];
  const double unit = 250 / (s * s) * std::abs(L.W.gradient_factor(L.dx)) * L.dx / P.mass[0];
  for (std::size_t i = 0; i < P.size(); ++i)
    ASSERT_LT(P.a[i].norm(), 1e-12 * unit) << "particle " << i;
}

TEST(Momentum, UniformPressureOnLatticeGivesNoAcceleration2D) {
  check_uniform_pressure_on_lattice<2>();
}
TEST(Momentum, UniformPressureOnLatticeGivesNoAcceleration3D) {
  check_uniform_pressure_on_lattice<3>();
}

template <int D>
void check_uniform_velocity_no_viscous_force() {
  Lattice<D> L(D == 2 ? 20 : 10, 1.3, 0.3);
  auto& P = L.P;
  Vec<D> u;
  for (int d = 0; d < D; ++d) u[d] = 0.7 - 0.5 * d;
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.v[i] = u;
    P.p[i] = 0;
    P.sigma[i] = P.rho[i] / P.mass[i];
  }
  const auto F = params<D>(3.0);
  pair_terms(P, L, F, true, no_gradient<D>());  // continuity: div u = 0 too
  for (std::size_t i = 0; i < P.size(); ++i) {
    ASSERT_EQ(P.a[i].norm(), 0.0) << "particle " << i;
    ASSERT_EQ(P.drho[i], 0.0) << "particle " << i;
  }
}

TEST(Momentum, UniformVelocityHasNoViscousForce2D) {
  check_uniform_velocity_no_viscous_force<2>();
}
TEST(Momentum, UniformVelocityHasNoViscousForce3D) {
  check_uniform_velocity_no_viscous_force<3>();
}

// Whole solver steps on a periodic Taylor–Green box: particle count and total mass are
// unchanged, total momentum (zero initially) stays zero to round-off.
void check_solver_conserves(const std::string& density) {
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.05, h_over_dx: 1.3}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids: [{rho0: 1.0, viscosity: 0.01, region: {box: {min: [0, 0], max: [1, 1]}}}]
initial: {taylor_green: {U: 1.0}}
eos: {type: linear, c0: 10.0, p0: 5.0}
time: {end: 1.0, cfl: 0.25}
)");
  root["density"] = YAML::Load(density);
  const Case c = read_case(root, "momentum_test");
  Solver<2> s(c);
  s.initialize();
  const auto& P = s.particles();
  const std::size_t n = P.size();
  double mass = 0, speed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mass += P.mass[i];
    speed += P.mass[i] * P.v[i].norm();
  }
  ASSERT_EQ(n, 400u);
  for (int k = 0; k < 30; ++k) s.step();
  ASSERT_EQ(P.size(), n);
  double mass_after = 0;
  Vec<2> momentum = Vec<2>::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    mass_after += P.mass[i];
    momentum += P.mass[i] * P.v[i];
  }
  EXPECT_NEAR(mass_after, mass, 1e-14 * mass);
  EXPECT_LT(momentum.norm(), 1e-12 * speed) << momentum.transpose();
}

TEST(Momentum, SolverConservesMassAndMomentumSummation) {
  check_solver_conserves("{method: summation}");
}
TEST(Momentum, SolverConservesMassAndMomentumContinuity) {
  check_solver_conserves("{method: continuity, delta_sph: 0.1, shifting: 0.02}");
}

}  // namespace
}  // namespace curvsph
