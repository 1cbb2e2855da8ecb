// Ghost maps (DESIGN.md §4): mirror, mirror_beta (Barker eqs. 17-19), density_preserving
// (Vela Vela eq. 13) against the papers' closed forms, and the set-up refusal.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "curvsph/boundary/ghost/ghost_map.hpp"
#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/torus.hpp"

using namespace curvsph;

namespace {

const double kDepths[] = {1e-6, 0.01, 0.05, 0.1, 0.2, 0.3};

// Vela Vela eq. 21 (cylinder / 2-D circle of radius R, paper coordinate r = R + s). Fluid
// inside: the particle is at s = -d and the ghost at psi = zeta' > 0. Fluid outside (an
// obstacle): the particle at s = +d and the ghost at psi = -zeta'.
double cylinder_inside(double R, double d) {
  return std::sqrt(2 * R * R - (R - d) * (R - d)) - R;
}
double cylinder_outside(double R, double d) {
  return -(std::sqrt(2 * R * R - (R + d) * (R + d)) - R);
}
// Vela Vela eq. 25 (sphere).
double sphere_inside(double R, double d) {
  return std::cbrt(2 * R * R * R - std::pow(R - d, 3)) - R;
}
double sphere_outside(double R, double d) {
  return -(std::cbrt(2 * R * R * R - std::pow(R + d, 3)) - R);
}
// Vela Vela eqs. 28-29 (torus, major R, minor a, poloidal angle theta): g(x) = B x^3/3 + x^2/2
// with B = cos(theta)/R, psi = g^{-1}(2 g(a) - g(a + s)) - a; g^{-1} by bisection in long
// double on the branch where g' = x (1 + B x) > 0.
long double torus_g(long double B, long double x) {
  return B * x * x * x / 3 + x * x / 2;
}
double torus_psi(double R, double a, double theta, double s) {
  const long double B = std::cos(static_cast<long double>(theta)) / R;
  const long double target = 2 * torus_g(B, a) - torus_g(B, a + s);
  long double lo = 0, hi = B < 0 ? -1 / B : 10 * (a + std::abs(s));
  for (int it = 0; it < 300; ++it) {
    const long double mid = (lo + hi) / 2;
    (torus_g(B, mid) < target ? lo : hi) = mid;
  }
  return static_cast<double>((lo + hi) / 2 - a);
}

double dp(double d, double k1, double k2) {
  const GhostDepth g = ghost_density_preserving(d, k1, k2);
  EXPECT_TRUE(g.ok) << "d=" << d << " k1=" << k1 << " k2=" << k2;
  EXPECT_EQ(g.beta, 1.0);
  return g.depth;
}

}  // namespace

TEST(GhostMap, ParseNames) {
  EXPECT_EQ(parse_ghost_map("mirror"), GhostMapKind::mirror);
  EXPECT_EQ(parse_ghost_map("mirror_beta"), GhostMapKind::mirror_beta);
  EXPECT_EQ(parse_ghost_map("density_preserving"), GhostMapKind::density_preserving);
  EXPECT_THROW(parse_ghost_map("mirrors", "case.yaml", "boundary.ghost.map"), InputError);
  EXPECT_EQ(parse_ghost_velocity("free_slip"), GhostVelocity::free_slip);
  EXPECT_THROW(parse_ghost_velocity("slip"), InputError);
}

TEST(GhostMap, DensityPreservingTendsToMirror) {
  for (double d : kDepths) {
    EXPECT_EQ(dp(d, 0.0, 0.0), d);
    // zeta' = d - (k1 + k2) d^2 + O(k^2 d^3): the difference from the mirror vanishes
    // linearly in the curvature.
    for (double k : {1e-2, 1e-4, 1e-6}) {
      for (auto [k1, k2] :
           {std::pair{k, 0.0}, std::pair{k, k}, std::pair{k, -0.5 * k}, std::pair{-k, -k}}) {
        const double z = dp(d, k1, k2);
        EXPECT_NEAR(z, d - (k1 + k2) * d * d, 4 * (k1 * k1 + k2 * k2 + 1e-300) * d * d * d + 1e-15)
            << d << " " << k1 << " " << k2;
      }
    }
  }
}

TEST(GhostMap, FastPathAgreesWithSafeguardedSolver) {
  // The hot-loop solver and the bracketed one agree to round-off wherever a root exists,
  // including deep particles (k d up to 0.9) where the fast path hands over.
  int checked = 0;
  for (double k1 : {-3.0, -1.0, -0.2, 0.0, 0.5, 1.0, 4.0})
    for (double k2 : {-3.0, -1.0, -0.2, 0.0, 0.5, 1.0, 4.0})
      for (double d : {1e-9, 1e-3, 0.02, 0.1, 0.2, 0.3, 0.5, 0.9}) {
        if (k2 > k1) continue;
        const GhostDepth fast = ghost_density_preserving(d, k1, k2);
        const GhostDepth safe = ghost_density_preserving_safe(d, k1, k2);
        ASSERT_EQ(fast.ok, safe.ok) << k1 << " " << k2 << " " << d;
        if (1 - k1 * d <= 0) {
          EXPECT_FALSE(safe.ok);  // deeper than the wall allows
        }
        if (!safe.ok) continue;
        EXPECT_NEAR(fast.depth, safe.depth, 4e-16 * safe.depth) << k1 << " " << k2 << " " << d;
        // Residual at round-off.
        const double t = -ghost_volume_g(k1, k2, -d);
        EXPECT_NEAR(ghost_volume_g(k1, k2, fast.depth), t, 1e-15 * t);
        ++checked;
      }
  EXPECT_GT(checked, 150);
}

TEST(GhostMap, CylinderMatchesVelaVelaEq21) {
  for (double R : {0.5, 1.0, 3.0}) {
    for (double d : kDepths) {
      if (d > 0.25 * R) continue;
      // Fluid inside (pipe; 2-D circle: k2 = 0 too), fluid outside (obstacle).
      EXPECT_NEAR(dp(d, 1 / R, 0.0), cylinder_inside(R, d), 1e-12 * R);
      EXPECT_NEAR(dp(d, 0.0, -1 / R), cylinder_outside(R, d), 1e-12 * R);
    }
    // Fluid inside: every depth up to the axis has a root.
    EXPECT_NEAR(dp(0.99 * R, 1 / R, 0.0), cylinder_inside(R, 0.99 * R), 1e-12 * R);
  }
}

TEST(GhostMap, SphereMatchesVelaVelaEq25) {
  for (double R : {0.5, 1.0, 3.0}) {
    for (double d : kDepths) {
      if (d > 0.25 * R) continue;
      EXPECT_NEAR(dp(d, 1 / R, 1 / R), sphere_inside(R, d), 1e-12 * R);
      EXPECT_NEAR(dp(d, -1 / R, -1 / R), sphere_outside(R, d), 1e-12 * R);
    }
    EXPECT_NEAR(dp(0.99 * R, 1 / R, 1 / R), sphere_inside(R, 0.99 * R), 1e-12 * R);
  }
}

TEST(GhostMap, TorusMatchesVelaVelaEq28) {
  for (double ratio : {2.0, 2.5, 3.0, 10.0}) {
    const double a = 1.0, R = ratio * a;
    for (double theta : {0.0, 0.7, M_PI / 2, 2.0, 2.8, M_PI}) {
      // Our convention: k = 1/a around the tube, cos(theta)/(R + a cos(theta)) along the
      // major circle, for fluid inside; negated for fluid outside (ring obstacle).
      const double kt = 1 / a, km = std::cos(theta) / (R + a * std::cos(theta));
      for (double d : {1e-6, 0.01, 0.1, 0.3, 0.9}) {
        EXPECT_NEAR(dp(d, std::max(kt, km), std::min(kt, km)), torus_psi(R, a, theta, -d), 1e-12)
            << "inside R/a=" << ratio << " theta=" << theta << " d=" << d;
        if (d <= 0.3) {
          EXPECT_NEAR(dp(d, std::max(-kt, -km), std::min(-kt, -km)), -torus_psi(R, a, theta, d),
                      1e-12)
              << "outside R/a=" << ratio << " theta=" << theta << " d=" << d;
        }
      }
    }
  }
}

TEST(GhostMap, TorusWallCurvaturesGiveVelaVelaMap) {
  // End to end: the TorusWall's own curvatures at a point's foot give eq. 28's ghost.
  const double R = 3.0, a = 1.0;
  const TorusWall torus(Vec3d::Zero(), Vec3d::UnitZ(), R, a, FluidSide::inside);
  for (double theta : {0.0, 1.0, M_PI / 2, 2.5, M_PI}) {
    const double d = 0.07, r = a - d;
    const Vec3d x((R + r * std::cos(theta)) * std::cos(0.3),
                  (R + r * std::cos(theta)) * std::sin(0.3), r * std::sin(theta));
    const WallPoint<3> p = torus.closest(x);
    ASSERT_NEAR(p.distance, d, 1e-12);
    EXPECT_NEAR(dp(p.distance, p.k1, p.k2), torus_psi(R, a, theta, -d), 1e-12) << theta;
  }
}

TEST(GhostMap, MirrorBetaMatchesBarkerEqs17To19) {
  for (double R : {0.5, 1.0, 4.0}) {
    for (double d : {0.01, 0.1, 0.2}) {
      // Eq. 17: circle with the fluid inside, beta = (R + d)/(R - d).
      GhostDepth g = ghost_mirror_beta(d, 1 / R, 0.0);
      ASSERT_TRUE(g.ok);
      EXPECT_EQ(g.depth, d);
      EXPECT_NEAR(g.beta, (R + d) / (R - d), 1e-14 * g.beta);
      // Eq. 18 with kappa < 0 (obstacle) and eq. 19 in 3-D.
      for (auto [k1, k2] : {std::pair{-1 / R, 0.0}, std::pair{1 / R, 1 / R},
                            std::pair{1 / R, -0.5 / R}, std::pair{-1 / R, -1 / R}}) {
        g = ghost_mirror_beta(d, k1, k2);
        ASSERT_TRUE(g.ok);
        EXPECT_NEAR(g.beta, (1 + k1 * d) / (1 - k1 * d) * (1 + k2 * d) / (1 - k2 * d), 1e-14);
      }
    }
  }
  const GhostDepth m = ghost_mirror(0.1, 1.0, 1.0);
  EXPECT_TRUE(m.ok);
  EXPECT_EQ(m.depth, 0.1);
  EXPECT_EQ(m.beta, 1.0);
}

TEST(GhostMap, GhostLayerVolumeEqualsMirroredFluidVolume) {
  // G(zeta') = -G(-d) <=> int_0^zeta' J = int_{-d}^0 J: integrate J numerically (composite
  // Gauss-Legendre, 3 points per panel) on both sides.
  auto integrate = [](double k1, double k2, double a, double b) {
    const int panels = 200;
    const double xg[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
    const double wg[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    double sum = 0, hpan = (b - a) / panels;
    for (int p = 0; p < panels; ++p)
      for (int q = 0; q < 3; ++q)
        sum +=
            wg[q] * 0.5 * hpan * ghost_jacobian(k1, k2, a + hpan * (p + 0.5) + 0.5 * hpan * xg[q]);
    return sum;
  };
  for (auto [k1, k2] : {std::pair{1.0, 0.0}, std::pair{0.0, -1.0}, std::pair{1.0, 1.0},
                        std::pair{-1.0, -1.0}, std::pair{1.0, -0.5}, std::pair{3.0, 0.2}}) {
    for (double d : {0.01, 0.1, 0.2}) {
      const double z = dp(d, k1, k2);
      const double fluid = integrate(k1, k2, -d, 0.0), ghost = integrate(k1, k2, 0.0, z);
      EXPECT_NEAR(ghost, fluid, 1e-13) << k1 << " " << k2 << " " << d;
      // The mirror's layer has the wrong volume wherever the wall is curved.
      if (k1 + k2 != 0) {
        EXPECT_GT(std::abs(integrate(k1, k2, 0.0, d) - fluid), 1e-4 * d);
      }
    }
  }
}

TEST(GhostMap, NoRootIsReportedNotInvented) {
  // Circle obstacle R = 1: behind the wall the layer holds at most G(1) = 1/2, reached by
  // d = sqrt(2) - 1; deeper particles have no ghost.
  EXPECT_TRUE(ghost_density_preserving(0.41, 0.0, -1.0).ok);
  EXPECT_FALSE(ghost_density_preserving(0.42, 0.0, -1.0).ok);
  EXPECT_FALSE(ghost_density_preserving(0.42, -1.0, -1.0).ok);
  EXPECT_FALSE(ghost_mirror(1.0, 0.0, -1.0).ok);
  EXPECT_FALSE(ghost_mirror_beta(1.2, -1.0, -1.0).ok);
  EXPECT_FALSE(ghost_density_preserving(0.0, 1.0, 0.0).ok);
  EXPECT_NEAR(ghost_max_depth(GhostMapKind::density_preserving, 0.0, -2.0),
              0.5 * (std::sqrt(2.0) - 1), 1e-12);
  EXPECT_NEAR(ghost_max_depth(GhostMapKind::density_preserving, -2.0, -2.0),
              0.5 * (std::cbrt(2.0) - 1), 1e-12);
  EXPECT_NEAR(ghost_max_depth_convex(GhostMapKind::density_preserving, 3, 0.5),
              0.5 * (std::cbrt(2.0) - 1), 1e-12);
  EXPECT_EQ(ghost_max_depth(GhostMapKind::mirror, 0.0, -2.0), 0.5);
  EXPECT_TRUE(std::isinf(ghost_max_depth(GhostMapKind::density_preserving, 1.0, 1.0)));
  EXPECT_TRUE(std::isinf(ghost_max_depth(GhostMapKind::mirror_beta, 0.0, 0.0)));
}

TEST(GhostMap, RefusesSmallConvexObstacle) {
  // 2-D circle obstacle of radius 0.1 with fluid around; 2h = 0.05 > 0.1 (sqrt 2 - 1).
  WallSet<2> walls;
  walls.add(std::make_shared<CircleWall>(Vec2d(0, 0), 0.1, FluidSide::outside));
  std::vector<Vec2> x;
  for (int k = 0; k < 16; ++k) x.emplace_back(0.13 * std::cos(0.4 * k), 0.13 * std::sin(0.4 * k));
  try {
    check_ghost_walls(GhostMapKind::density_preserving, walls, 0.05, x, "case.yaml");
    FAIL() << "expected a refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "walls.0");
    EXPECT_EQ(e.file(), "case.yaml");
    const std::string r = e.reason();
    EXPECT_NE(r.find("circle"), std::string::npos) << r;
    EXPECT_NE(r.find("radius of curvature 0.1"), std::string::npos) << r;
    EXPECT_NE(r.find("h < 0.0207107"), std::string::npos) << r;
  }
  EXPECT_NO_THROW(check_ghost_walls(GhostMapKind::density_preserving, walls, 0.04, x, "c"));
  // The mirror only needs 2h below the radius; the same support is fine for it.
  EXPECT_NO_THROW(check_ghost_walls(GhostMapKind::mirror, walls, 0.05, x, "c"));
  EXPECT_THROW(check_ghost_walls(GhostMapKind::mirror_beta, walls, 0.11, x, "c"), InputError);
  // Without samples: the convex worst case of the smallest radius.
  EXPECT_THROW(check_ghost_walls(GhostMapKind::density_preserving, walls, 0.05, {}, "c"),
               InputError);
  // A big obstacle, a tank (concave: no convex limit; its radius 0.1 against 2h is
  // test_concave_refusal.cpp's), a 3-D sphere obstacle.
  WallSet<2> big, tank;
  big.add(std::make_shared<CircleWall>(Vec2d(0, 0), 1.0, FluidSide::outside));
  tank.add(std::make_shared<CircleWall>(Vec2d(0, 0), 0.1, FluidSide::inside));
  std::vector<Vec2> xt{Vec2(0.05, 0.0), Vec2(0.0, -0.09)};
  EXPECT_NO_THROW(check_ghost_walls(GhostMapKind::density_preserving, big, 0.1, x, "c"));
  EXPECT_NO_THROW(check_ghost_walls(GhostMapKind::density_preserving, tank, 0.1, xt, "c"));
  WallSet<3> ball;
  ball.add(std::make_shared<SphereWall>(Vec3d::Zero(), 0.1, FluidSide::outside));
  std::vector<Vec3> x3{Vec3(0.12, 0, 0)};
  EXPECT_THROW(check_ghost_walls(GhostMapKind::density_preserving, ball, 0.03, x3, "c"),
               InputError);
  EXPECT_NO_THROW(check_ghost_walls(GhostMapKind::density_preserving, ball, 0.025, x3, "c"));
}

TEST(GhostMap, RefusesTorusWithAspectBelowTwoNearTheHole) {
  // Fluid inside the tube: at the inner equator the wall is concave around the tube (1/a)
  // and convex along the major circle (-1/(R - a)), so the ghosts head for the torus axis.
  // For R/a >= 2 every depth up to a has a root; for R/a < 2 a support close to a puts
  // ghosts beyond the axis (Vela Vela Fig. 4), while a thin support is still fine.
  const double a = 1.0;
  auto tube_points = [&](double R) {
    std::vector<Vec3> x;
    for (int i = 0; i < 12; ++i)
      for (int j = 1; j <= 4; ++j) {
        const double th = 2 * M_PI * i / 12, r = a * (1 - 0.2 * j);
        x.emplace_back(R + r * std::cos(th), 0.0, r * std::sin(th));
      }
    return x;
  };
  for (double ratio : {1.5, 1.8, 1.95}) {
    WallSet<3> walls;
    walls.add(std::make_shared<TorusWall>(Vec3d::Zero(), Vec3d::UnitZ(), ratio * a, a,
                                          FluidSide::inside));
    EXPECT_THROW(check_ghost_walls(GhostMapKind::density_preserving, walls, 0.99 * a,
                                   tube_points(ratio * a), "c"),
                 InputError)
        << ratio;
    EXPECT_NO_THROW(check_ghost_walls(GhostMapKind::density_preserving, walls, 0.1 * a,
                                      tube_points(ratio * a), "c"));
  }
  for (double ratio : {2.0, 2.5, 3.0}) {
    WallSet<3> walls;
    walls.add(std::make_shared<TorusWall>(Vec3d::Zero(), Vec3d::UnitZ(), ratio * a, a,
                                          FluidSide::inside));
    EXPECT_NO_THROW(check_ghost_walls(GhostMapKind::density_preserving, walls, 0.99 * a,
                                      tube_points(ratio * a), "c"))
        << ratio;
  }
  // Vela Vela: at R/a = 2 the map at the inner equator is exactly the mirror.
  EXPECT_NEAR(dp(0.6, 1.0, -1.0), 0.6, 1e-14);
}
