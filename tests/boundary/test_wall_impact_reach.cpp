// The reach of the impact pressure (boundary/wall_impact.hpp item 1): only a particle about to
// touch its wall feels it. One particle in a tank without gravity, at distance d above the
// floor and far from the other walls, once at rest and once moving into the floor at U; the
// difference of its accelerations is the impact term alone. References, written out here from
// the kernel (not from the boundary code):
// - boundary integrals: a = c0 U S(d) / gamma(d) (the impact pressure rho c0 U over the wall
//   elements, sum_b W A n = S n, divided by rho gamma), with S(d) = int W(sqrt(d^2 + s^2)) ds
//   along the floor and gamma(d) = int_{y > -d} W dA the geometric Shepard factor, both by
//   Simpson's rule;
// - mirror ghosts: the particle's own ghost at 2d below it, a = -(rho c0 U) V^2 F(2d) 2d / m
//   (the pair term of a ghost of pressure rho c0 U and the particle's volume V = m/rho = dx^2,
//   F the kernel's gradient factor, grad W = F r);
// each times the documented taper of its family: 1 up to `full` dx, 0 from `zero` dx on
// (kImpactReachIntegrals, kImpactReachGhosts).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>

#include "curvsph/boundary/wall_impact.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

constexpr double kDx = 0.01, kH = 0.02, kC0 = 10, kRho = 1000, kU = 0.5;

YAML::Node lone_particle(const std::string& boundary) {
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.01, h_over_dx: 2}
fluids: [{rho0: 1000, viscosity: 0, region: {box: {min: [0.1, 0.05], max: [0.11, 0.06]}}}]
eos: {type: linear, c0: 10, p0: 0}
density: {method: continuity, delta_sph: 0}
gravity: [0, 0]
walls: [{shape: box, min: [0, 0], max: [0.2, 0.2], fluid: inside}]
time: {end: 1.0}
output: {vtk: false}
)");
  root["boundary"] = YAML::Load(boundary);
  return root;
}

// The particle's acceleration at (0.1, d), velocity (0, -u).
Vec2 acceleration(const YAML::Node& root, double d, double u) {
  const Case c = read_case(YAML::Clone(root), "wall_impact_reach");
  Solver<2> first(c);
  first.initialize();
  Particles<2> P = first.particles();
  EXPECT_EQ(P.size(), 1u);
  P.x[0] = Vec2(Real(0.1), static_cast<Real>(d));
  P.v[0] = Vec2(0, static_cast<Real>(-u));
  Solver<2> s(c);
  s.restart(P, 0);
  s.initialize();
  return s.particles().a[0];
}

double simpson(double a, double b, int n, auto f) {
  const double step = (b - a) / n;
  double sum = f(a) + f(b);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * f(a + k * step);
  return sum * step / 3;
}

double integrals_reference(double d) {
  const WendlandC2<2> W(static_cast<Real>(kH));
  const double R = 2 * kH;
  const auto w = [&](double r) { return static_cast<double>(W.value(static_cast<Real>(r))); };
  const double S = simpson(-R, R, 2000, [&](double s) { return w(std::sqrt(d * d + s * s)); });
  // gamma: the kernel over the half plane y > -d, in slices y = const.
  const double gamma = simpson(-d, R, 2000, [&](double y) {
    if (std::abs(y) >= R) return 0.0;
    const double half = std::sqrt(R * R - y * y);
    return simpson(-half, half, 400, [&](double x) { return w(std::sqrt(x * x + y * y)); });
  });
  return kC0 * kU * S / gamma;
}

double ghost_reference(double d) {
  const WendlandC2<2> W(static_cast<Real>(kH));
  const double V = kDx * kDx;  // m / rho: continuity density, 1/sigma of the particle
  return -(kRho * kC0 * kU) * V * V / (kRho * V) * W.gradient_factor(static_cast<Real>(2 * d)) * 2 *
         d;
}

// The documented taper (wall_impact.hpp): 1 to `full` dx, 0 from `zero` dx, the cubic
// smoothstep 3 s^2 - 2 s^3 between.
double taper(double d, double a, double b) {
  const double q = d / kDx;
  if (q <= a) return 1;
  if (q >= b) return 0;
  const double s = (b - q) / (b - a);
  return s * s * (3 - 2 * s);
}

void expect_reach(const YAML::Node& root, double (*reference)(double), double a, double b) {
  // Within the full zone, half-way through the taper, and 2 dx off the wall.
  for (const double q : {0.5 * a, 0.5 * (a + b), 2.0}) {
    const double d = q * kDx;
    const Vec2 diff = acceleration(root, d, kU) - acceleration(root, d, 0);
    const double ref = reference(d) * taper(d, a, b);
    if (q >= b) {
      EXPECT_EQ(diff.norm(), 0) << "d = " << q << " dx";
    } else {
      EXPECT_NEAR(diff.y(), ref, 0.02 * ref) << "d = " << q << " dx";
      EXPECT_NEAR(diff.x(), 0, 1e-6 * ref) << "d = " << q << " dx";
    }
  }
  EXPECT_NEAR(taper(0.5 * (a + b) * kDx, a, b), 0.5, 1e-12);
}

TEST(WallImpactReach, IntegralsPushOnlyAParticleAboutToTouchItsWall) {
  // The documented reach: full to dx/4, none from 3 dx/4.
  ASSERT_DOUBLE_EQ(kImpactReachIntegrals.full, Real(0.25));
  ASSERT_DOUBLE_EQ(kImpactReachIntegrals.zero, Real(0.75));
  expect_reach(lone_particle("{method: integrals, shepard: geometric}"), integrals_reference, 0.25,
               0.75);
}

TEST(WallImpactReach, GhostsPushOnlyAParticleAboutToTouchItsWall) {
  // The documented reach: full to dx/2, none from dx.
  ASSERT_DOUBLE_EQ(kImpactReachGhosts.full, Real(0.5));
  ASSERT_DOUBLE_EQ(kImpactReachGhosts.zero, Real(1));
  expect_reach(lone_particle("{method: ghost, map: mirror, velocity: no_slip}"), ghost_reference,
               0.5, 1.0);
}

TEST(WallImpactReach, TaperIsFullAtContactAndZeroBeyondItsReach) {
  // rho c0 U at contact, nothing at 2 dx, nothing for a receding particle.
  EXPECT_DOUBLE_EQ(wall_impact_pressure(1000, 28, Real(0.25), Real(0), kImpactReachIntegrals),
                   7000);
  EXPECT_DOUBLE_EQ(wall_impact_pressure(1000, 28, Real(0.25), Real(2), kImpactReachGhosts), 0);
  EXPECT_DOUBLE_EQ(wall_impact_pressure(1000, 28, Real(-0.25), Real(0), kImpactReachGhosts), 0);
}

}  // namespace
}  // namespace curvsph
