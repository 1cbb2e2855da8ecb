// Infinite walls' boundary elements clipped by the other walls (boundary/integrals/wall_clip.hpp):
// the kept lengths and areas against the exact wetted parts, and the geometric Shepard factor
// near the corner of two and three clipped planes against adaptive quadrature of W over the
// fluid (tests/support/shepard_reference.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <numeric>

#include "../support/shepard_reference.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/wall_clip.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/geometry/plane.hpp"
#include "curvsph/geometry/sphere.hpp"

using namespace curvsph;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double h = 1.0, dx = 0.5;  // h / dx = 2

template <int D>
double total_area(const BoundaryElements<D>& el) {
  return std::accumulate(el.area.begin(), el.area.end(), 0.0);
}

// The elements of every wall as the solver builds them (IntegralsBoundary::build_elements);
// clip = false: the generators' alone (each infinite wall cut by the box only).
template <int D>
BoundaryElements<D> elements(const WallSet<D>& walls, double spacing, const Bounds<D>& box,
                             bool clip = true) {
  BoundaryElements<D> out;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const auto e = elements_from_wall<D>(walls[k], spacing, box);
    out.append(clip ? clip_by_other_walls<D>(e, walls, k, 1e-9 * spacing) : e);
  }
  return out;
}

// Floor y = 0 and the plane through the origin at angle alpha: the wedge 0 <= angle <= alpha.
WallSet<2> wedge_planes(double alpha) {
  WallSet<2> w;
  w.add(std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(0, 1)));
  w.add(std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(std::sin(alpha), -std::cos(alpha))));
  return w;
}

}  // namespace

TEST(WallClip, PlanesMeetingAtAnAngleGammaAgainstQuadrature) {
  // The box runs 3 h past the apex, so that unclipped each plane runs on behind the other.
  const Bounds<2> box(Vec2d(-3, -3), Vec2d(6, 6));
  double worst = 0, worst_unclipped = 0;
  for (double deg : {60.0, 90.0, 120.0}) {
    const double alpha = deg * pi / 180;
    const WallSet<2> walls = wedge_planes(alpha);
    const auto el = elements<2>(walls, dx, box);
    const auto raw = elements<2>(walls, dx, box, false);
    // The floor from the apex to x = 6, the other plane from the apex to the box.
    const Vec2d t(std::cos(alpha), std::sin(alpha));
    const double s_end = std::min(t.x() > 0 ? 6 / t.x() : 1e9, t.x() < 0 ? -3 / t.x() : 1e9);
    EXPECT_NEAR(total_area(el), 6 + std::min(s_end, 6 / t.y()), 1e-12) << deg;
    auto inside = [alpha](const Vec2d& y) {
      return y[1] >= 0 && std::sin(alpha) * y[0] - std::cos(alpha) * y[1] >= 0;
    };
    const Vec2d bis(std::cos(alpha / 2), std::sin(alpha / 2));
    for (int k = 0; k <= 24; ++k) {
      const double s = 3 * h * (1 - k / 24.0);
      // Along the bisector, along the floor 0.25 dx above it, and on the floor.
      for (const Vec2d& x : {Vec2d(s * bis), Vec2d(s, 0.25 * dx), Vec2d(s, 0)}) {
        if (!inside(x)) continue;
        const double ref = test::reference_gamma_2d(x, h, inside);
        const double e = std::abs(shepard_geometric<2>(el, x, h) - ref);
        worst = std::max(worst, e);
        worst_unclipped =
            std::max(worst_unclipped, std::abs(shepard_geometric<2>(raw, x, h) - ref));
        EXPECT_NEAR(shepard_geometric<2>(el, x, h), ref, 0.005) << deg << ": " << x.transpose();
      }
    }
  }
  std::printf("wedge of planes: |gamma - quadrature| <= %.2e clipped, %.2e unclipped\n", worst,
              worst_unclipped);
  EXPECT_GT(worst_unclipped, 0.05);  // the fault the clipping removes
}

TEST(WallClip, FloorUnderACircleSunkIntoItOrAboveIt) {
  const Bounds<2> box(Vec2d(-3, -3), Vec2d(3, 3));
  for (const double yc : {0.5, -0.5, 1.5}) {
    WallSet<2> walls;
    walls.add(std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(0, 1)));
    walls.add(std::make_shared<CircleWall>(Vec2d(0.1, yc), 1.0, FluidSide::outside));
    const auto floor =
        clip_by_other_walls<2>(elements_from_wall<2>(walls[0], 0.1, box), walls, 0, 1e-10);
    // The floor inside the disc (its chord |x - 0.1| < sqrt(R^2 - yc^2)) is the obstacle's solid.
    const double chord = yc * yc < 1 ? 2 * std::sqrt(1 - yc * yc) : 0.0;
    EXPECT_NEAR(total_area(floor), 6 - chord, 1e-10) << yc;
    // The circle itself is finite: left whole.
    const auto circle = elements_from_wall<2>(walls[1], 0.1, box);
    EXPECT_EQ(clip_by_other_walls<2>(circle, walls, 1, 1e-10).size(), circle.size());
  }
}

TEST(WallClip, OpenWallsClipNothing) {
  // An open baffle (degree-1 NURBS from (-1, 1) to (1, 1)): its sign flips beyond its ends,
  // below it the fluid goes on, and the floor under it stays whole.
  nurbs::NurbsCurve<2> c(1, {Vec2d(-1, 1), Vec2d(1, 1)}, {}, {0, 0, 1, 1});
  const auto baffle = std::make_shared<NurbsCurveWall>(std::move(c), NurbsCurveWall::Side::left);
  EXPECT_FALSE(clips_by_sign<2>(*baffle));
  WallSet<2> walls;
  walls.add(std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(0, 1)));
  walls.add(baffle);
  const Bounds<2> box(Vec2d(-3, -3), Vec2d(3, 3));
  EXPECT_NEAR(total_area(elements<2>(walls, 0.1, box)), 6 + 2, 1e-12);
}

TEST(WallClip, ThreePlanesAtACornerAreTheWettedFaces) {
  // Floor z = 0 and walls x = 0, y = 0 in the box [-0.5, 2]^3: each plane keeps its 2 x 2
  // wetted face (unclipped: 2.5 x 2.5 each). An oblique fourth plane x + y >= 0.5 cuts every
  // face across its elements (Sutherland & Hodgman, fanned): the floor keeps 4 - 0.125.
  const Bounds<3> box(Vec3d(-0.5, -0.5, -0.5), Vec3d(2, 2, 2));
  WallSet<3> walls;
  walls.add(std::make_shared<PlaneWall<3>>(Vec3d(0, 0, 0), Vec3d(0, 0, 1)));
  walls.add(std::make_shared<PlaneWall<3>>(Vec3d(0, 0, 0), Vec3d(1, 0, 0)));
  walls.add(std::make_shared<PlaneWall<3>>(Vec3d(0, 0, 0), Vec3d(0, 1, 0)));
  EXPECT_NEAR(total_area(elements<3>(walls, 0.1, box)), 12, 1e-10);
  EXPECT_NEAR(total_area(elements<3>(walls, 0.1, box, false)), 3 * 6.25, 1e-10);
  walls.add(std::make_shared<PlaneWall<3>>(Vec3d(0.25, 0.25, 0), Vec3d(1, 1, 0).normalized()));
  const auto floor =
      clip_by_other_walls<3>(elements_from_wall<3>(walls[0], 0.1, box), walls, 0, 1e-10);
  EXPECT_NEAR(total_area(floor), 4 - 0.125, 1e-10);
  // The side x = 0 keeps y in [0.5, 2], z in [0, 2]; y = 0 likewise.
  const auto side =
      clip_by_other_walls<3>(elements_from_wall<3>(walls[1], 0.1, box), walls, 1, 1e-10);
  EXPECT_NEAR(total_area(side), 1.5 * 2, 1e-10);
  for (std::size_t j = 0; j < floor.size(); ++j)
    EXPECT_GT(floor.centre[j].x() + floor.centre[j].y(), 0.5);
}

TEST(WallClip, ThreePlanesAtACornerGammaAgainstQuadrature) {
  const Bounds<3> box(Vec3d(-3, -3, -3), Vec3d(5, 5, 5));
  WallSet<3> walls;
  walls.add(std::make_shared<PlaneWall<3>>(Vec3d(0, 0, 0), Vec3d(0, 0, 1)));
  walls.add(std::make_shared<PlaneWall<3>>(Vec3d(0, 0, 0), Vec3d(1, 0, 0)));
  walls.add(std::make_shared<PlaneWall<3>>(Vec3d(0, 0, 0), Vec3d(0, 1, 0)));
  const auto el = elements<3>(walls, dx, box);
  const test::Columns octant = [](double X, double Y) {
    return X >= 0 && Y >= 0 ? std::vector<std::pair<double, double>>{{0.0, 1e9}}
                            : std::vector<std::pair<double, double>>{};
  };
  double worst = 0;
  for (const Vec3d& x : {Vec3d(0.3, 0.3, 0.3), Vec3d(0.8, 0.8, 0.8), Vec3d(0.25, 1.0, 0.25),
                         Vec3d(0.1, 0.6, 1.2), Vec3d(1.5, 0.2, 0.1)}) {
    const double ref = test::reference_gamma_3d(x, h, octant, 1e-6);
    const double g = shepard_geometric<3>(el, x, h);
    worst = std::max(worst, std::abs(g - ref));
    EXPECT_NEAR(g, ref, 0.005) << x.transpose();
  }
  std::printf("octant of planes: |gamma - quadrature| <= %.2e\n", worst);
}

TEST(WallClip, CurvedWallsCutPlanesAndPlanesCutCylinders) {
  // A floor z = 0 under a sphere of radius 1 sunk 0.5 into it (fluid outside): the floor loses
  // the disc of radius sqrt(0.75), cut along chords of the elements it crosses: each chord of
  // length c leaves c^3 kappa / 12 of the disc (the circular segment), about 2 pi r / c chords
  // of at most c = sqrt(2) L: at most pi c^2 / 6 = pi L^2 / 3 in all, whatever the radius. A
  // sphere above the floor leaves it whole.
  const Bounds<3> box(Vec3d(-2, -2, -2), Vec3d(2, 2, 2));
  const double spacing = 0.1;
  for (const double zc : {0.5, 1.5}) {
    WallSet<3> walls;
    walls.add(std::make_shared<PlaneWall<3>>(Vec3d(0, 0, 0), Vec3d(0, 0, 1)));
    walls.add(std::make_shared<SphereWall>(Vec3d(0.03, 0.02, zc), 1.0, FluidSide::outside));
    const auto floor =
        clip_by_other_walls<3>(elements_from_wall<3>(walls[0], spacing, box), walls, 0, 1e-10);
    const double disc = zc < 1 ? pi * (1 - zc * zc) : 0.0;
    const double err = total_area(floor) - (16 - disc);
    std::printf("floor under a sphere at z = %.1f: area error %.2e (disc %.3f)\n", zc, err, disc);
    // Chords inside the circle: the kept area is a little larger than exact.
    EXPECT_GE(err, -1e-10);
    EXPECT_LT(err, pi * spacing * spacing / 3);
  }
  // A vertical cylinder of radius 1 (fluid inside) standing on the floor: the cylinder's patches
  // below it dropped or cut across the axis (exact: 2 pi R x 2), the floor kept inside it (the
  // disc up to its chords).
  WallSet<3> walls;
  walls.add(std::make_shared<PlaneWall<3>>(Vec3d(0, 0, 0), Vec3d(0, 0, 1)));
  walls.add(std::make_shared<CylinderWall>(Vec3d(0, 0, 0), Vec3d(0, 0, 1), 1.0, FluidSide::inside));
  const Bounds<3> tall(Vec3d(-2, -2, -0.55), Vec3d(2, 2, 2));  // the floor cuts a row of patches
  const auto cyl =
      clip_by_other_walls<3>(elements_from_wall<3>(walls[1], spacing, tall), walls, 1, 1e-10);
  const auto full = elements_from_wall<3>(walls[1], spacing, tall);
  EXPECT_NEAR(total_area(cyl), total_area(full) * 2 / 2.55, 1e-10);
  for (std::size_t j = 0; j < cyl.size(); ++j) {
    EXPECT_NEAR(std::hypot(cyl.centre[j].x(), cyl.centre[j].y()),
                std::hypot(full.centre[0].x(), full.centre[0].y()), 1e-12);
    EXPECT_GE(cyl.centre[j].z(), 0.0);
  }
  const auto floor =
      clip_by_other_walls<3>(elements_from_wall<3>(walls[0], spacing, tall), walls, 0, 1e-10);
  const double err = total_area(floor) - pi;
  std::printf("floor inside a cylinder: area error %.2e\n", err);
  EXPECT_LE(err, 1e-10);  // chords inside the circle: a little less than the disc
  EXPECT_GT(err, -pi * spacing * spacing / 3);
}
