// Ghost generation (GhostSet): positions against hand-computed ones, corners, velocities,
// periodic wrap, penetration report, determinism and reuse.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "curvsph/analysis/ghost_cost.hpp"
#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/moving_wall.hpp"
#include "curvsph/geometry/plane.hpp"

using namespace curvsph;

namespace {

template <int D>
GhostOptions<D> options(GhostMapKind map, Real support,
                        GhostVelocity vel = GhostVelocity::no_slip) {
  GhostOptions<D> o;
  o.map = map;
  o.support = support;
  o.velocity = vel;
  return o;
}

// Index of the ghost at position p (or -1).
template <int D>
int find(const GhostSet<D>& g, const Vec<D>& p, double tol = 1e-12) {
  for (std::size_t k = 0; k < g.size(); ++k)
    if ((g.x[k] - p).norm() < tol) return static_cast<int>(k);
  return -1;
}

}  // namespace

TEST(GhostSet, CircleTankAllMaps) {
  WallSet<2> walls;
  walls.add(std::make_shared<CircleWall>(Vec2d(0, 0), 1.0, FluidSide::inside));
  const std::vector<Vec2> x{Vec2(0.9, 0.0), Vec2(0.0, 0.0), Vec2(0.0, -0.95)};
  const std::vector<Vec2> v(3, Vec2(0.3, -0.2));
  GhostSet<2> g;
  g.build(x, v, walls, options<2>(GhostMapKind::mirror, 0.2));
  ASSERT_EQ(g.size(), 2u);
  EXPECT_NEAR((g.x[0] - Vec2(1.1, 0.0)).norm(), 0, 1e-12);
  EXPECT_NEAR((g.x[1] - Vec2(0.0, -1.05)).norm(), 0, 1e-12);
  EXPECT_EQ(g.source[0], 0);
  EXPECT_EQ(g.source[1], 2);
  EXPECT_EQ(g.wall[0], 0);
  EXPECT_EQ(g.beta[0], 1);
  EXPECT_NEAR(g.source_depth[0], 0.1, 1e-12);
  EXPECT_NEAR((g.normal[0] - Vec2d(-1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((g.foot[0] - Vec2d(1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((g.v[0] + v[0]).norm(), 0, 1e-12);  // no-slip mirror: -u

  g.build(x, v, walls, options<2>(GhostMapKind::mirror_beta, 0.2));
  ASSERT_EQ(g.size(), 2u);
  EXPECT_NEAR(g.beta[0], 1.1 / 0.9, 1e-12);
  EXPECT_NEAR(g.beta[1], 1.05 / 0.95, 1e-12);

  // Density preserving: r_g^2 = 2 R^2 - r^2 (area between the circles preserved).
  g.build(x, v, walls, options<2>(GhostMapKind::density_preserving, 0.2));
  ASSERT_EQ(g.size(), 2u);
  EXPECT_NEAR((g.x[0] - Vec2(std::sqrt(2 - 0.81), 0.0)).norm(), 0, 1e-12);
  EXPECT_NEAR((g.x[1] - Vec2(0.0, -std::sqrt(2 - 0.9025))).norm(), 0, 1e-12);
  EXPECT_EQ(g.beta[0], 1);
  // No-slip extrapolation to the ghost's own depth: u_g = -(zeta'/d) u.
  const double ratio = (std::sqrt(2 - 0.81) - 1) / 0.1;
  EXPECT_NEAR((g.v[0] + ratio * v[0]).norm(), 0, 1e-12);
  EXPECT_TRUE(g.penetrated.empty());
  EXPECT_TRUE(g.no_root.empty());
}

TEST(GhostSet, CircleObstacle) {
  WallSet<2> walls;
  walls.add(std::make_shared<CircleWall>(Vec2d(0, 0), 1.0, FluidSide::outside));
  const std::vector<Vec2> x{Vec2(0.0, 1.05), Vec2(-1.1, 0.0)};
  const std::vector<Vec2> v(2, Vec2::Zero());
  GhostSet<2> g;
  g.build(x, v, walls, options<2>(GhostMapKind::mirror, 0.2));
  ASSERT_EQ(g.size(), 2u);
  EXPECT_NEAR((g.x[0] - Vec2(0.0, 0.95)).norm(), 0, 1e-12);
  EXPECT_NEAR((g.x[1] - Vec2(-0.9, 0.0)).norm(), 0, 1e-12);
  g.build(x, v, walls, options<2>(GhostMapKind::density_preserving, 0.2));
  EXPECT_NEAR((g.x[0] - Vec2(0.0, std::sqrt(2 - 1.05 * 1.05))).norm(), 0, 1e-12);
}

TEST(GhostSet, BoxCornerDoubleReflection2D) {
  WallSet<2> walls;
  walls.add(std::make_shared<BoxWall<2>>(Vec2d(0, 0), Vec2d(1, 1), FluidSide::inside));
  const std::vector<Vec2> x{Vec2(0.05, 0.1), Vec2(0.5, 0.5), Vec2(0.5, 0.95)};
  const std::vector<Vec2> v{Vec2(1, 2), Vec2(1, 2), Vec2(1, 2)};
  GhostSet<2> g;
  g.build(x, v, walls, options<2>(GhostMapKind::density_preserving, 0.2));
  ASSERT_EQ(g.size(), 4u);
  const int a = find(g, Vec2(-0.05, 0.1)), b = find(g, Vec2(0.05, -0.1)),
            c = find(g, Vec2(-0.05, -0.1)), d = find(g, Vec2(0.5, 1.05));
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  ASSERT_GE(c, 0);
  ASSERT_GE(d, 0);
  EXPECT_EQ(g.reflections[c], 2);
  EXPECT_EQ(g.reflections[a], 1);
  EXPECT_EQ(g.source[c], 0);
  EXPECT_EQ(g.source[d], 2);
  // No-slip, stationary: single ghosts -u, the corner ghost (-(-u)) = u.
  EXPECT_NEAR((g.v[a] - Vec2(-1, -2)).norm(), 0, 1e-12);
  EXPECT_NEAR((g.v[c] - Vec2(1, 2)).norm(), 0, 1e-12);
  // Free slip: the normal component is reflected.
  g.build(x, v, walls, options<2>(GhostMapKind::mirror, 0.2, GhostVelocity::free_slip));
  EXPECT_NEAR((g.v[find(g, Vec2(-0.05, 0.1))] - Vec2(-1, 2)).norm(), 0, 1e-12);
  EXPECT_NEAR((g.v[find(g, Vec2(0.05, -0.1))] - Vec2(1, -2)).norm(), 0, 1e-12);
  EXPECT_NEAR((g.v[find(g, Vec2(-0.05, -0.1))] - Vec2(-1, -2)).norm(), 0, 1e-12);
}

TEST(GhostSet, BoxCorner3DAndPlanesMeeting) {
  WallSet<3> box;
  box.add(std::make_shared<BoxWall<3>>(Vec3d(0, 0, 0), Vec3d(1, 1, 1), FluidSide::inside));
  const std::vector<Vec3> x{Vec3(0.05, 0.1, 0.15)};
  const std::vector<Vec3> v{Vec3::Zero()};
  GhostSet<3> g;
  g.build(x, v, box, options<3>(GhostMapKind::mirror, 0.2));
  ASSERT_EQ(g.size(), 7u);  // 3 faces, 3 edges, 1 vertex
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (int sz : {1, -1}) {
        if (sx == 1 && sy == 1 && sz == 1) continue;
        const int k = find(g, Vec3(0.05 * sx, 0.1 * sy, 0.15 * sz));
        ASSERT_GE(k, 0) << sx << sy << sz;
        EXPECT_EQ(g.reflections[k], (sx < 0) + (sy < 0) + (sz < 0));
      }

  // Two plane walls meeting at a right angle (2-D): the same three ghosts; a third plane at
  // 45 degrees to the first adds its single ghost only: their lines meet at (0, -0.2), behind
  // the second plane, and its 135 degree corner with the second cuts no single of this point
  // (flat_corners.hpp; test_flat_corners.cpp).
  WallSet<2> planes;
  planes.add(std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(1, 0)));
  planes.add(std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(0, 1)));
  GhostSet<2> g2;
  const std::vector<Vec2> x2{Vec2(0.05, 0.1)};
  const std::vector<Vec2> v2{Vec2(1, 2)};
  g2.build(x2, v2, planes, options<2>(GhostMapKind::mirror, 0.2));
  ASSERT_EQ(g2.size(), 3u);
  EXPECT_GE(find(g2, Vec2(-0.05, 0.1)), 0);
  EXPECT_GE(find(g2, Vec2(0.05, -0.1)), 0);
  EXPECT_GE(find(g2, Vec2(-0.05, -0.1)), 0);
  EXPECT_EQ(g2.wall[find(g2, Vec2(0.05, -0.1))], 1);
  planes.add(std::make_shared<PlaneWall<2>>(Vec2d(0.2, 0), Vec2d(-1, 1)));
  g2.build(x2, v2, planes, options<2>(GhostMapKind::mirror, 0.2));
  EXPECT_EQ(g2.size(), 4u);
}

TEST(GhostSet, MovingWallVelocities) {
  // Plane y = 0 moving with u_w = (2, 0): no-slip u_g = 2 u_w - u; free slip keeps the
  // tangential relative velocity and reflects the normal one.
  WallMotion<2> slide;
  slide.kind = WallMotion<2>::Kind::translate;
  slide.velocity = Vec2d(2, 0);
  WallSet<2> walls;
  walls.add(std::make_shared<MovingWall<2>>(
      std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(0, 1)), slide));
  const std::vector<Vec2> x{Vec2(0.3, 0.05)};
  const std::vector<Vec2> v{Vec2(1, 0.5)};
  GhostSet<2> g;
  g.build(x, v, walls, options<2>(GhostMapKind::mirror, 0.2));
  ASSERT_EQ(g.size(), 1u);
  EXPECT_NEAR((g.v[0] - Vec2(3, -0.5)).norm(), 0, 1e-12);
  g.build(x, v, walls, options<2>(GhostMapKind::mirror, 0.2, GhostVelocity::free_slip));
  EXPECT_NEAR((g.v[0] - Vec2(1, -0.5)).norm(), 0, 1e-12);

  // Rotating circle tank (omega = 1): wall speed at the foot (1, 0) is (0, 1).
  WallMotion<2> spin;
  spin.kind = WallMotion<2>::Kind::rotate;
  spin.omega = 1.0;
  WallSet<2> tank;
  tank.add(std::make_shared<MovingWall<2>>(
      std::make_shared<CircleWall>(Vec2d(0, 0), 1.0, FluidSide::inside), spin));
  const std::vector<Vec2> xc{Vec2(0.9, 0.0)};
  const std::vector<Vec2> vc{Vec2(0.0, 0.5)};
  g.build(xc, vc, tank, options<2>(GhostMapKind::density_preserving, 0.2));
  ASSERT_EQ(g.size(), 1u);
  const double ratio = g.depth[0] / 0.1;
  EXPECT_NEAR((g.v[0] - Vec2(0.0, 1.0 - ratio * (0.5 - 1.0))).norm(), 0, 1e-12);
}

TEST(GhostSet, PenetrationReported) {
  WallSet<2> walls;
  walls.add(std::make_shared<CircleWall>(Vec2d(0, 0), 1.0, FluidSide::inside));
  walls.add(std::make_shared<BoxWall<2>>(Vec2d(-2, -2), Vec2d(2, 2), FluidSide::inside));
  const std::vector<Vec2> x{Vec2(0.5, 0), Vec2(1.01, 0), Vec2(0.0, 0.95), Vec2(2.5, 0),
                            Vec2(0, 1.0)};
  const std::vector<Vec2> v(x.size(), Vec2::Zero());
  GhostSet<2> g;
  g.build(x, v, walls, options<2>(GhostMapKind::mirror, 0.2));
  EXPECT_EQ(g.penetrated, (std::vector<Index>{1, 3, 4}));
  for (std::size_t k = 0; k < g.size(); ++k) EXPECT_EQ(g.source[k], 2);
}

TEST(GhostSet, NoRootReported) {
  WallSet<2> walls;
  walls.add(std::make_shared<CircleWall>(Vec2d(0, 0), 0.1, FluidSide::outside));
  const std::vector<Vec2> x{Vec2(0.145, 0), Vec2(0.12, 0)};  // depths 0.045 and 0.02
  const std::vector<Vec2> v(2, Vec2::Zero());
  GhostSet<2> g;
  g.build(x, v, walls, options<2>(GhostMapKind::density_preserving, 0.05));
  EXPECT_EQ(g.no_root, (std::vector<Index>{0}));
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g.source[0], 1);
}

TEST(GhostSet, PeriodicWrap) {
  // Floor y = 0 in a domain periodic in y on [-0.1, 1): the ghost below wraps to the top.
  WallSet<2> walls;
  walls.add(std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(0, 1)));
  CellList<2> cells;
  cells.configure(0.2, Vec3d(0, -0.1, 0), Vec3d(1, 1.0, 0), {false, true, false});
  auto o = options<2>(GhostMapKind::mirror, 0.2);
  o.cells = &cells;
  const std::vector<Vec2> x{Vec2(0.5, 0.15)};
  const std::vector<Vec2> v{Vec2::Zero()};
  GhostSet<2> g;
  g.build(x, v, walls, o);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_NEAR((g.x[0] - Vec2(0.5, 0.95)).norm(), 0, 1e-12);
}

TEST(GhostSet, DeterministicAndReused) {
  WallSet<2> walls;
  walls.add(std::make_shared<CircleWall>(Vec2d(0, 0), 1.0, FluidSide::inside));
  walls.add(std::make_shared<PlaneWall<2>>(Vec2d(0, -0.8), Vec2d(0, 1)));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec2> x, v;
  while (x.size() < 20000) {
    const Vec2 p(u(rng), u(rng));
    if (p.norm() < 1 && p.y() > -0.8) {
      x.push_back(p);
      v.emplace_back(u(rng), u(rng));
    }
  }
  const int threads = omp_get_max_threads();
  GhostSet<2> one, many;
  omp_set_num_threads(1);
  one.build(x, v, walls, options<2>(GhostMapKind::density_preserving, 0.1));
  omp_set_num_threads(std::max(2, threads));
  many.build(x, v, walls, options<2>(GhostMapKind::density_preserving, 0.1));
  ASSERT_GT(one.size(), 1000u);
  ASSERT_EQ(one.size(), many.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    ASSERT_EQ(one.x[k], many.x[k]);
    ASSERT_EQ(one.v[k], many.v[k]);
    ASSERT_EQ(one.source[k], many.source[k]);
    if (k) {
      ASSERT_LE(one.source[k - 1], one.source[k]);
    }
  }
  // Rebuilding with the same particles reuses the arrays.
  const auto* px = many.x.data();
  const auto* pf = many.foot.data();
  many.build(x, v, walls, options<2>(GhostMapKind::density_preserving, 0.1));
  EXPECT_EQ(px, many.x.data());
  EXPECT_EQ(pf, many.foot.data());
  omp_set_num_threads(threads);
}

TEST(GhostCost, StudyRunsSmall) {
  GhostCostOptions o;
  o.particles = 20000;
  o.repeats = 1;
  const GhostCostResult r = ghost_cost_study(o);
  ASSERT_EQ(r.shapes.size(), 3u);
  for (const auto& s : r.shapes) {
    EXPECT_GT(s.ghosts, 1000u) << s.shape;
    EXPECT_GT(s.mirror_s, 0) << s.shape;
    EXPECT_TRUE(std::isfinite(s.increase_pct)) << s.shape;
  }
  EXPECT_EQ(r.metrics.count("ghost_cost_increase_pct_torus"), 1u);
}
