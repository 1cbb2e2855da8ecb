// The ghosts' share of the continuity equation takes the free-slip image of the velocity even
// with `velocity: no_slip` (ghosts.hpp). Reference: a divergence-free linear flow
// u = (a x, -a y) in the corner of two plane walls (x = 0, y = 0), which it does not cross,
// on a lattice whose images continue it: the SPH divergence of a linear field over a full,
// symmetric lattice support is A : (c I) = c tr A = 0, so every particle whose support is
// filled by fluid and ghosts keeps its density. The no-slip image (u_g = -u_s) reverses the
// tangential part of the flow and gave these particles a rate of order rho a.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>

#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

constexpr double kA = 1.0;  // strain rate, 1/s

// Water in the corner, open (free surface) on the two far sides, inviscid so that the ghost
// velocity enters the continuity equation only; one step of at most 1e-7 s.
Case corner(const std::string& velocity) {
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.001, h_over_dx: 1.3}
domain: {min: [0, 0], max: [0.03, 0.02]}
fluids: [{rho0: 1000, viscosity: 0, region: {box: {min: [0, 0], max: [0.03, 0.02]}}}]
eos: {type: tait, c0: 10, gamma: 7, p0: 0}
density: {method: continuity, delta_sph: 0}
walls:
  - {shape: plane, point: [0, 0], normal: [0, 1]}
  - {shape: plane, point: [0, 0], normal: [1, 0]}
time: {end: 1.0e-7, dt_max: 1.0e-7}
output: {vtk: false}
)");
  root["boundary"] = YAML::Load("{method: ghost, map: mirror, velocity: " + velocity + "}");
  return read_case(root, "ghost_continuity_test");
}

// Largest |drho/dt| / (rho a) over particles within 2h of a wall whose support the open
// sides do not cut, after one step of the linear flow.
double wall_rate(const std::string& velocity, int& counted) {
  const Case c = corner(velocity);
  Solver<2> s(c);
  s.initialize();
  auto& P = s.particles();
  for (std::size_t i = 0; i < P.size(); ++i)
    P.v[i] = Vec2(static_cast<Real>(kA * P.x[i].x()), static_cast<Real>(-kA * P.x[i].y()));
  s.step();
  const double support = 2 * c.h();
  double worst = 0;
  counted = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double x = P.x[i].x(), y = P.x[i].y();
    const bool near_wall = x < support || y < support;
    const bool full = x < 0.03 - support && y < 0.02 - support;
    if (!near_wall || !full) continue;
    ++counted;
    worst = std::max(worst, std::abs(static_cast<double>(P.drho[i])) / (1000 * kA));
  }
  return worst;
}

TEST(GhostContinuity, NoSlipWallsKeepALinearDivergenceFreeFlowAtItsDensity) {
  int n_free = 0, n_noslip = 0;
  const double free_slip = wall_rate("free_slip", n_free);
  const double no_slip = wall_rate("no_slip", n_noslip);
  EXPECT_GT(n_noslip, 100);
  EXPECT_EQ(n_free, n_noslip);
  // The step moves the lattice by a x dt = 3e-8 m at most: an affine strain of 1e-7, which is
  // the rate left over (the exact rate is 0).
  EXPECT_LT(free_slip, 1e-5);
  EXPECT_LT(no_slip, 1e-5);
}

}  // namespace
}  // namespace curvsph
