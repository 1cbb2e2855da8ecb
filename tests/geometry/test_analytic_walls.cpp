// Closed-form checks of every analytic wall: foot, normal into the fluid, signed distance,
// principal curvatures with the sign convention of DESIGN.md §4, parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/ellipse.hpp"
#include "curvsph/geometry/plane.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/torus.hpp"

namespace curvsph {
namespace {

constexpr double kTol = 1e-13;
constexpr double kPi = std::numbers::pi;

template <int D>
void expect_vec(const VecD<D>& a, const VecD<D>& b, double tol = kTol) {
  EXPECT_LT((a - b).norm(), tol) << "got " << a.transpose() << " expected " << b.transpose();
}

TEST(GeometryPlane, TwoDimensional) {
  const PlaneWall<2> w(Vec2d(0, 1), Vec2d(0, 2));  // the line y = 1, fluid above
  const auto p = w.closest(Vec2d(3, 0.5));
  expect_vec<2>(p.foot, Vec2d(3, 1));
  expect_vec<2>(p.normal, Vec2d(0, 1));
  EXPECT_NEAR(p.distance, -0.5, kTol);
  EXPECT_EQ(p.k1, 0.0);
  EXPECT_EQ(p.param_count, 1);
  EXPECT_NEAR(p.param[0], -3.0, kTol);  // tangent perp(n) = (-1, 0)
  EXPECT_TRUE(std::isinf(w.min_radius_of_curvature()));
}

TEST(GeometryPlane, ThreeDimensional) {
  const PlaneWall<3> w(Vec3d(0, 0, 0), Vec3d(1, 1, 1));
  const Vec3d n = Vec3d(1, 1, 1).normalized();
  const auto p = w.closest(Vec3d(1, 2, 3));
  EXPECT_NEAR(p.distance, 6.0 / std::sqrt(3.0), kTol);
  expect_vec<3>(p.normal, n);
  expect_vec<3>(p.foot, Vec3d(1, 2, 3) - p.distance * n);
  EXPECT_NEAR(p.dir1.dot(n), 0.0, kTol);
  EXPECT_NEAR(p.dir2.dot(n), 0.0, kTol);
  EXPECT_NEAR(p.dir1.dot(p.dir2), 0.0, kTol);
  EXPECT_EQ(p.param_count, 2);
}

TEST(GeometryCircle, FluidInsideAndOutside) {
  const double R = 2.0;
  const CircleWall in(Vec2d(1, 1), R, FluidSide::inside);
  const CircleWall out(Vec2d(1, 1), R, FluidSide::outside);
  const Vec2d x(1.0 + 0.5 * std::sqrt(0.5), 1.0 + 0.5 * std::sqrt(0.5));  // rho = 0.5, 45 deg
  const auto a = in.closest(x);
  expect_vec<2>(a.foot, Vec2d(1 + R * std::sqrt(0.5), 1 + R * std::sqrt(0.5)));
  expect_vec<2>(a.normal, Vec2d(-std::sqrt(0.5), -std::sqrt(0.5)));
  EXPECT_NEAR(a.distance, 1.5, kTol);
  EXPECT_NEAR(a.k1, 1.0 / R, kTol);
  EXPECT_EQ(a.k2, 0.0);
  EXPECT_NEAR(a.param[0], kPi / 4, kTol);
  const auto b = out.closest(x);
  expect_vec<2>(b.normal, Vec2d(std::sqrt(0.5), std::sqrt(0.5)));
  EXPECT_NEAR(b.distance, -1.5, kTol);
  EXPECT_NEAR(b.k1, -1.0 / R, kTol);
  // The centre: a consistent answer (u = 0), distance R.
  const auto c = in.closest(Vec2d(1, 1));
  expect_vec<2>(c.foot, Vec2d(1 + R, 1));
  EXPECT_NEAR(c.distance, R, kTol);
}

TEST(GeometryEllipse, CurvatureAtTheTips) {
  const double a = 3.0, b = 0.5;
  const EllipseWall in(Vec2d(0, 0), a, b, FluidSide::inside);
  const EllipseWall out(Vec2d(0, 0), a, b, FluidSide::outside);
  // Tip of the major axis: k = a / b^2; of the minor axis: k = b / a^2.
  const auto tip_a = in.closest(Vec2d(3.5, 0.0));
  expect_vec<2>(tip_a.foot, Vec2d(a, 0));
  EXPECT_NEAR(tip_a.k1, a / (b * b), 1e-12);
  EXPECT_NEAR(tip_a.distance, -0.5, kTol);
  expect_vec<2>(tip_a.normal, Vec2d(-1, 0));
  const auto tip_b = in.closest(Vec2d(0.0, 0.2));
  expect_vec<2>(tip_b.foot, Vec2d(0, b));
  EXPECT_NEAR(tip_b.k1, b / (a * a), 1e-14);
  EXPECT_NEAR(tip_b.distance, 0.3, kTol);
  EXPECT_NEAR(tip_b.param[0], kPi / 2, kTol);
  const auto o = out.closest(Vec2d(-4.0, 0.0));
  expect_vec<2>(o.foot, Vec2d(-a, 0));
  EXPECT_NEAR(o.k1, -a / (b * b), 1e-12);
  EXPECT_NEAR(o.distance, 1.0, kTol);
  expect_vec<2>(o.normal, Vec2d(-1, 0));
  EXPECT_NEAR(in.min_radius_of_curvature(), b * b / a, kTol);
  // Tall ellipse (b > a): the tips swap roles.
  const EllipseWall tall(Vec2d(0, 0), b, a, FluidSide::inside);
  EXPECT_NEAR(tall.closest(Vec2d(0, 2.95)).k1, a / (b * b), 1e-12);
}

TEST(GeometryEllipse, GeneralPointAgainstParametricForm) {
  // Pick a foot, step along its normal, and recover it.
  const double a = 2.0, b = 1.0;
  const EllipseWall w(Vec2d(0.5, -0.5), a, b, FluidSide::outside);
  for (double t : {0.3, 1.2, 2.0, -2.7, -0.1}) {
    const Vec2d f(a * std::cos(t), b * std::sin(t));
    const Vec2d n = Vec2d(f.x() / (a * a), f.y() / (b * b)).normalized();
    for (double s : {0.01, 0.3, 2.0}) {
      const auto p = w.closest(Vec2d(0.5, -0.5) + f + s * n);
      expect_vec<2>(p.foot, Vec2d(0.5, -0.5) + f, 1e-12);
      EXPECT_NEAR(p.distance, s, 1e-12);
      EXPECT_NEAR(p.param[0], t, 1e-12);
      const double k =
          a * b /
          std::pow(a * a * std::sin(t) * std::sin(t) + b * b * std::cos(t) * std::cos(t), 1.5);
      EXPECT_NEAR(p.k1, -k, 1e-12);
    }
  }
}

TEST(GeometryEllipse, CentreAndAxes) {
  const EllipseWall w(Vec2d(0, 0), 2.0, 1.0, FluidSide::inside);
  const auto c = w.closest(Vec2d(0, 0));
  expect_vec<2>(c.foot, Vec2d(0, 1));
  EXPECT_NEAR(c.distance, 1.0, kTol);
  // On the major axis inside the evolute segment |x| < (a^2 - b^2)/a = 1.5: foot off-axis.
  const auto m = w.closest(Vec2d(0.75, 0));
  expect_vec<2>(m.foot, Vec2d(1.0, std::sqrt(0.75)), 1e-14);
  const auto t = w.closest(Vec2d(1.8, 0));
  expect_vec<2>(t.foot, Vec2d(2, 0));
  EXPECT_NEAR(t.distance, 0.2, kTol);
  // A circle given as an ellipse agrees with the circle.
  const EllipseWall circ(Vec2d(0, 0), 1.5, 1.5, FluidSide::inside);
  const auto q = circ.closest(Vec2d(0.3, 0.4));
  EXPECT_NEAR(q.distance, 1.0, kTol);
  EXPECT_NEAR(q.k1, 1 / 1.5, kTol);
}

TEST(GeometryBox, FacesAndCorners2D) {
  const BoxWall<2> in(Vec2d(0, 0), Vec2d(2, 1), FluidSide::inside);
  const auto a = in.closest(Vec2d(1.7, 0.6));  // nearest face x = 2
  expect_vec<2>(a.foot, Vec2d(2, 0.6));
  expect_vec<2>(a.normal, Vec2d(-1, 0));
  EXPECT_NEAR(a.distance, 0.3, kTol);
  EXPECT_EQ(a.k1, 0.0);
  const auto b = in.closest(Vec2d(2.3, 1.4));  // outside, beyond the corner (2, 1)
  expect_vec<2>(b.foot, Vec2d(2, 1));
  EXPECT_NEAR(b.distance, -0.5, kTol);
  expect_vec<2>(b.normal, Vec2d(-0.6, -0.8));
  EXPECT_EQ(b.k1, 0.0);
  const BoxWall<2> out(Vec2d(0, 0), Vec2d(2, 1), FluidSide::outside);
  const auto c = out.closest(Vec2d(-0.3, -0.4));
  expect_vec<2>(c.foot, Vec2d(0, 0));
  EXPECT_NEAR(c.distance, 0.5, kTol);
  expect_vec<2>(c.normal, Vec2d(-0.6, -0.8));
  const auto d = out.closest(Vec2d(0.5, 0.5));  // tie x=0 / y=0 / y=1: -x face first
  expect_vec<2>(d.foot, Vec2d(0, 0.5));
  EXPECT_NEAR(d.distance, -0.5, kTol);
  expect_vec<2>(d.normal, Vec2d(-1, 0));
}

TEST(GeometryBox, EdgesAndFaces3D) {
  const BoxWall<3> out(Vec3d(0, 0, 0), Vec3d(1, 1, 1), FluidSide::outside);
  const auto e = out.closest(Vec3d(1.3, 1.4, 0.5));  // edge along z
  expect_vec<3>(e.foot, Vec3d(1, 1, 0.5));
  EXPECT_NEAR(e.distance, 0.5, kTol);
  expect_vec<3>(e.dir1, Vec3d(0, 0, 1));
  EXPECT_NEAR(e.dir2.dot(e.normal), 0.0, kTol);
  const auto f = out.closest(Vec3d(0.5, 0.5, 0.9));
  expect_vec<3>(f.foot, Vec3d(0.5, 0.5, 1));
  EXPECT_NEAR(f.distance, -0.1, kTol);
  expect_vec<3>(f.normal, Vec3d(0, 0, 1));
}

TEST(GeometryCylinder, CurvaturesAndDirections) {
  const double R = 0.5;
  const CylinderWall in(Vec3d(0, 0, 1), Vec3d(0, 0, 3), R, FluidSide::inside);
  const CylinderWall out(Vec3d(0, 0, 1), Vec3d(0, 0, 3), R, FluidSide::outside);
  const Vec3d x(0.0, 0.2, 7.0);
  const auto a = in.closest(x);
  expect_vec<3>(a.foot, Vec3d(0, R, 7));
  expect_vec<3>(a.normal, Vec3d(0, -1, 0));
  EXPECT_NEAR(a.distance, 0.3, kTol);
  EXPECT_NEAR(a.k1, 1 / R, kTol);
  EXPECT_NEAR(a.k2, 0.0, kTol);
  EXPECT_NEAR(std::abs(a.dir1.x()), 1.0, kTol);  // around the circle
  expect_vec<3>(a.dir2, Vec3d(0, 0, 1));
  EXPECT_NEAR(a.param[1], 6.0, kTol);
  const auto b = out.closest(x);
  EXPECT_NEAR(b.distance, -0.3, kTol);
  EXPECT_NEAR(b.k1, 0.0, kTol);
  EXPECT_NEAR(b.k2, -1 / R, kTol);
  expect_vec<3>(b.dir1, Vec3d(0, 0, 1));
}

TEST(GeometrySphere, CurvaturesAndParameters) {
  const SphereWall in(Vec3d(1, 0, 0), 2.0, FluidSide::inside);
  const SphereWall out(Vec3d(1, 0, 0), 2.0, FluidSide::outside);
  const Vec3d x(1.0, 3.0, 0.0);
  const auto a = in.closest(x);
  expect_vec<3>(a.foot, Vec3d(1, 2, 0));
  EXPECT_NEAR(a.distance, -1.0, kTol);
  EXPECT_NEAR(a.k1, 0.5, kTol);
  EXPECT_NEAR(a.k2, 0.5, kTol);
  EXPECT_NEAR(a.param[0], kPi / 2, kTol);
  EXPECT_NEAR(a.param[1], kPi / 2, kTol);
  const auto b = out.closest(x);
  EXPECT_NEAR(b.distance, 1.0, kTol);
  EXPECT_NEAR(b.k1, -0.5, kTol);
  expect_vec<3>(b.normal, Vec3d(0, 1, 0));
  const auto c = in.closest(Vec3d(1, 0, 0));
  expect_vec<3>(c.foot, Vec3d(1, 0, 2));
}

TEST(GeometryTorus, CurvatureAtSeveralPoloidalAngles) {
  const double R = 1.0, a = 0.4;
  const Vec3d c(0.5, -0.2, 0.3);
  const Vec3d axis = Vec3d(0.2, -0.3, 1.0).normalized();
  const TorusWall in(c, axis, R, a, FluidSide::inside);
  const TorusWall out(c, axis, R, a, FluidSide::outside);
  const auto [e1, e2] = orthonormal_frame(axis);
  for (double phi : {0.0, 1.0, -2.5}) {
    const Vec3d radial = std::cos(phi) * e1 + std::sin(phi) * e2;
    for (double theta : {0.0, 0.5, kPi / 2, 2.0, kPi, -1.0, -kPi / 2}) {
      const Vec3d outward = std::cos(theta) * radial + std::sin(theta) * axis;
      const Vec3d foot = c + R * radial + a * outward;
      const double k_major = std::cos(theta) / (R + a * std::cos(theta));
      // Inside the tube, just outside, and outside but nearer this side than across the hole.
      for (double s : {-0.3, 0.05, 0.25}) {
        const Vec3d x = foot + s * outward;
        const auto p = in.closest(x);
        expect_vec<3>(p.foot, foot, 1e-13);
        EXPECT_NEAR(p.distance, -s, 1e-13);
        expect_vec<3>(p.normal, -outward, 1e-13);
        EXPECT_NEAR(p.k1, 1 / a, 1e-12);
        EXPECT_NEAR(p.k2, k_major, 1e-12);
        EXPECT_NEAR(std::abs(p.dir2.dot(axis.cross(radial))), 1.0, 1e-12);
        EXPECT_NEAR(std::remainder(p.param[0] - theta, 2 * kPi), 0.0, 1e-12);
        EXPECT_NEAR(std::remainder(p.param[1] - phi, 2 * kPi), 0.0, 1e-12);
        const auto q = out.closest(x);
        EXPECT_NEAR(q.distance, s, 1e-13);
        EXPECT_NEAR(q.k1, -k_major, 1e-12);
        EXPECT_NEAR(q.k2, -1 / a, 1e-12);
        EXPECT_GE(q.k1, q.k2);
      }
    }
  }
  EXPECT_NEAR(in.min_radius_of_curvature(), std::min(a, R - a), kTol);
}

TEST(GeometryTorus, AxisAndCentreCircleAreConsistent) {
  const TorusWall w(Vec3d(0, 0, 0), Vec3d(0, 0, 1), 1.0, 0.3, FluidSide::outside);
  const auto on_axis = w.closest(Vec3d(0, 0, 0.2));
  EXPECT_NEAR(on_axis.distance, std::hypot(1.0, 0.2) - 0.3, kTol);
  const auto core = w.closest(Vec3d(0, 1, 0));  // on the tube's centre circle
  EXPECT_NEAR(core.distance, -0.3, kTol);
  EXPECT_NEAR(core.param[0], 0.0, kTol);
  EXPECT_NEAR((core.foot - Vec3d(0, 1.3, 0)).norm(), 0.0, kTol);
}

TEST(GeometryWallSet, NearestWins) {
  WallSet<2> set;
  set.add(std::make_shared<CircleWall>(Vec2d(0, 0), 1.0, FluidSide::outside));
  set.add(std::make_shared<CircleWall>(Vec2d(0, 0), 3.0, FluidSide::inside));
  EXPECT_EQ(set.closest(Vec2d(1.5, 0)).wall, 0);
  EXPECT_EQ(set.closest(Vec2d(0, 2.5)).wall, 1);
}

}  // namespace
}  // namespace curvsph
