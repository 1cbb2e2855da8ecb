// Walls that move (geometry/moving_wall.hpp) in the solver: a slab of fluid between two plane
// pistons 0.1 apart, periodic along the pistons, both pistons translating at U from t = 0. No
// particle may cross a piston or be put back (particles_projected 0), and the fluid must go
// with them. Reference (linear acoustics of the impulsive start, in the pistons' frame): the
// fluid starts at -U in a closed box, so its mean velocity there is a triangle wave between
// -U and +U of period 2L/c0 whose time integral never exceeds U L/(4 c0); the fluid's centre
// of mass therefore stays within U L/(4 c0) = 0.25 dx of the pistons' midpoint x_mid(0) + U t
// (a wall that stayed put would leave it behind by U t, 4 dx at the end), and over whole
// periods the mean velocity averages to U. Both boundary families: ghosts, and boundary
// integrals, whose elements are generated once and moved with the wall.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

constexpr double kU = 0.1, kL = 0.1, kDx = 0.005, kC0 = 2.0;

std::string piston_case(const std::string& boundary) {
  return R"(
dimension: 2
resolution: {dx: 0.005, h_over_dx: 2}
domain: {min: [-0.1, 0], max: [0.3, 0.08], periodic: [false, true]}
fluids: [{rho0: 1, viscosity: 0.01, region: {box: {min: [0, 0], max: [0.1, 0.08]}}}]
eos: {type: linear, c0: 2, p0: 0.5}
walls:
  - {shape: plane, point: [0, 0], normal: [1, 0], motion: {translate: {velocity: [0.1, 0]}}}
  - {shape: plane, point: [0.1, 0], normal: [-1, 0], motion: {translate: {velocity: [0.1, 0]}}}
boundary: )" +
         boundary + R"(
time: {end: 0.2, cfl: 0.2}
)";
}

void run_piston(const std::string& boundary) {
  SCOPED_TRACE(boundary);
  const Case c = read_case(YAML::Load(piston_case(boundary)), "piston_test");
  Solver<2> s(c);
  s.initialize();
  const double period = 2 * kL / kC0;  // 0.1: the end time is two periods
  double worst_lag = 0, impulse_last_period = 0;
  while (s.time() < 0.2 - 1e-12) {
    s.step(static_cast<Real>(0.2 - s.time()));
    const auto& P = s.particles();
    const double t = s.time();
    const double left = kU * t, right = kL + kU * t;
    double xm = 0, vm = 0, xmin = 1e9, xmax = -1e9;
    for (std::size_t i = 0; i < P.size(); ++i) {
      xm += P.x[i].x();
      vm += P.v[i].x();
      xmin = std::min(xmin, static_cast<double>(P.x[i].x()));
      xmax = std::max(xmax, static_cast<double>(P.x[i].x()));
    }
    xm /= static_cast<double>(P.size());
    vm /= static_cast<double>(P.size());
    ASSERT_GT(xmin, left) << "a particle is behind the left piston at t = " << t;
    ASSERT_LT(xmax, right) << "a particle is behind the right piston at t = " << t;
    worst_lag = std::max(worst_lag, std::abs(xm - 0.5 * (left + right)));
    if (t > 0.2 - period) impulse_last_period += vm * s.dt();
  }
  EXPECT_EQ(s.stray_counts().projected, 0);
  EXPECT_EQ(s.stray_counts().removed, 0);
  std::printf(
      "%s: centre of mass within %.3g dx of the pistons' midpoint (bound 0.25 dx); mean "
      "velocity over the last period %.4f U\n",
      boundary.c_str(), worst_lag / kDx, impulse_last_period / period / kU);
  EXPECT_LT(worst_lag, 0.3 * kDx);                           // measured 0.23 dx (both families)
  EXPECT_NEAR(impulse_last_period / period, kU, 0.03 * kU);  // measured 1.005 U
}

TEST(MovingWalls, PistonsPushTheFluidWithoutCrossingGhosts) {
  run_piston("{method: ghost, map: mirror, velocity: no_slip}");
}

TEST(MovingWalls, PistonsPushTheFluidWithoutCrossingIntegrals) {
  run_piston("{method: integrals, shepard: geometric}");
}

}  // namespace
}  // namespace curvsph
