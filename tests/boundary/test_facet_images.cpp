// Ghost images at the corners of a polygon wall (boundary/ghost/facet_images.hpp). Reference:
// the kernel's own normalisation, int W = 1 over the plane. The fluid wedge and its images,
// integrated by a fine midpoint rule, must give 1 at every point near the corner (the support
// full); no image may lie on the fluid side.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "curvsph/boundary/ghost/facet_images.hpp"
#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/kernels/wendland.hpp"

namespace curvsph {
namespace {

constexpr double kPi = std::numbers::pi;

// A wedge of interior angle theta at the origin: face A along +x, face B along angle theta,
// both of length L; normals into the wedge.
struct Wedge {
  WallFacet<2> A, B;
  double theta;
  Wedge(double th, double L) : theta(th) {
    const Vec2d eb(std::cos(th), std::sin(th));
    A = {Vec2d(L, 0), Vec2d(0, 0), Vec2d(0, 1)};
    B = {Vec2d(0, 0), L * eb, Vec2d(eb.y(), -eb.x())};
  }
  bool inside(const Vec2d& p) const {  // in the fluid wedge (angle in (0, theta))
    double a = std::atan2(p.y(), p.x());
    if (a < 0) a += 2 * kPi;
    return a > 0 && a < theta;
  }
};

// int W(x0 - y) dy over the fluid wedge (within 4h of the corner) and over the images of its
// points: a midpoint rule in polar coordinates (n x n cells), each sample point handed to
// facet_images as a particle would be.
double shepard_at(const Wedge& w, const Vec2d& x0, double h, int n) {
  const WendlandC2<2> W(static_cast<Real>(h));
  const double support = 2 * h, R = 4 * h;
  const WallFacet<2> faces[2] = {w.A, w.B};
  double s = 0;
  const double dr = R / n, dphi = w.theta / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double r = (i + 0.5) * dr, phi = (j + 0.5) * dphi, dA = r * dr * dphi;
      const Vec2d x(r * std::cos(phi), r * std::sin(phi));
      // Only the faces within two supports are handed over, as the ghost builder does.
      WallFacet<2> near[2];
      int nf = 0;
      for (const auto& f : faces) {
        const Vec2d t = f.b - f.a;
        const double u = std::clamp((x - f.a).dot(t) / t.squaredNorm(), 0.0, 1.0);
        if ((x - (f.a + u * t)).norm() < 2 * support) near[nf++] = f;
      }
      FacetImage<2> im[32];
      const int ni = facet_images<2>(x, near, nf, support, im, 32);
      s += dA * W.value(static_cast<Real>((x - x0).norm()));
      for (int g = 0; g < ni; ++g) {
        EXPECT_FALSE(w.inside(im[g].x)) << "image of (" << x.transpose() << ") in the fluid";
        s += dA * W.value(static_cast<Real>((im[g].x - x0).norm()));
      }
    }
  return s;
}

class ConcaveCorner : public ::testing::TestWithParam<double> {};

TEST_P(ConcaveCorner, ImagesFillTheSupport) {
  const double theta = GetParam() * kPi / 180, h = 1.0;
  const Wedge w(theta, 10.0);
  // Points at 0.25 h and 1.5 h from the corner along two rays inside the wedge.
  double worst = 0;
  for (double frac : {0.2, 0.7})
    for (double r : {0.25, 1.5}) {
      const double a = frac * theta;
      worst = std::max(
          worst, std::abs(shepard_at(w, r * h * Vec2d(std::cos(a), std::sin(a)), h, 400) - 1));
    }
  // The midpoint rule on 400 x 400 cells: ~1e-5.
  EXPECT_LT(worst, 1e-4) << "theta = " << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Angles, ConcaveCorner, ::testing::Values(45.0, 60.0, 90.0, 120.0, 150.0));

class AnyAngleCorner : public ::testing::TestWithParam<double> {};

TEST_P(AnyAngleCorner, ImagesFillTheSupport) {
  // Angles that no reflection group tiles: the words of the two reflections up to length
  // ceil(pi/theta - 1/2), each image kept on its last face's side of the exterior bisector.
  // Reference 1 (int W over the plane), points at 0.25 h and 1.5 h on three rays, the middle
  // one the bisector, where the single images alone left a gap: their worst sums were 0.591
  // (50 degrees), 0.770 (75), 0.904 (100) and 0.952 (110; numpy, the same midpoint rule).
  // The midpoint rule's own error: ~1e-5, up to ~4e-4 where the bisector cuts its cells.
  const double theta = GetParam() * kPi / 180, h = 1.0;
  const Wedge w(theta, 10.0);
  double worst = 0;
  for (double frac : {0.2, 0.5, 0.7})
    for (double r : {0.25, 1.5}) {
      const double a = frac * theta;
      worst = std::max(
          worst, std::abs(shepard_at(w, r * h * Vec2d(std::cos(a), std::sin(a)), h, 400) - 1));
    }
  std::cout << GetParam() << " degree polygon corner: worst |sum - 1| " << worst << "\n";
  EXPECT_LT(worst, 1e-3) << "theta = " << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Angles, AnyAngleCorner, ::testing::Values(50.0, 75.0, 100.0, 110.0));

TEST(ConvexCorner, VertexRegionGetsThePointReflectionOnly) {
  // Fluid outside a 90 degree corner (interior angle 270): the solid is x < 0, y < 0, face A
  // along the negative x axis (normal +y), B along the negative y axis (normal +x). The point
  // (0.3, 0.4) projects beyond both faces: the vertex is its closest point.
  WallFacet<2> faces[2] = {{Vec2d(-5, 0), Vec2d(0, 0), Vec2d(0, 1)},
                           {Vec2d(0, 0), Vec2d(0, -5), Vec2d(1, 0)}};
  FacetImage<2> im[32];
  int n = facet_images<2>(Vec2d(0.3, 0.4), faces, 2, 2.0, im, 32);
  ASSERT_EQ(n, 1);
  EXPECT_NEAR((im[0].x - Vec2d(-0.3, -0.4)).norm(), 0, 1e-14);
  EXPECT_NEAR(im[0].source_depth, 0.5, 1e-14);
  // Above face A, left of the vertex: A's single image only.
  n = facet_images<2>(Vec2d(-0.3, 0.4), faces, 2, 2.0, im, 32);
  ASSERT_EQ(n, 1);
  EXPECT_NEAR((im[0].x - Vec2d(-0.3, -0.4)).norm(), 0, 1e-14);
  EXPECT_EQ(im[0].reflections, 1);
}

TEST(PolygonWall, SideAtAnAcuteVertexFromThePseudoNormal) {
  // A 60 degree corner at the origin (floor along +x, side along 60 degrees), fluid inside.
  // Reference: the wedge itself (polar angle in (0, 60 degrees)). Points around the vertex, in
  // and out, whose closest point is the vertex or a face: the sign of the distance must say
  // which; one face's normal alone put points beside the vertex, outside, on the fluid side.
  const double c = std::cos(kPi / 3), s = std::sin(kPi / 3);
  const WallPtr<2> w = make_nurbs_curve_wall(
      YAML::Load(
          fmt::format("{{shape: nurbs_curve, degree: 1, fluid: left, knots: [0, 0, 1, 2, 2], "
                      "control_points: [[{}, {}], [0, 0], [1, 0]]}}",
                      c, s)),
      "poly.yaml", "walls.0");
  const Wedge wedge(kPi / 3, 1.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-0.2, 0.2);
  int wrong = 0, n = 0;
  for (int k = 0; k < 4000; ++k) {
    const Vec2d x(U(rng), U(rng));
    const WallPoint<2> p = w->closest(x);
    if (std::abs(p.distance) < 1e-12) continue;
    ++n;
    wrong += (p.distance > 0) != wedge.inside(x);
    EXPECT_NEAR(std::abs(p.distance),
                std::min({(x - Vec2d::Zero()).norm(), x.x() >= 0 ? std::abs(x.y()) : 1e9,
                          x.dot(Vec2d(c, s)) >= 0 ? std::abs(x.dot(Vec2d(-s, c))) : 1e9}),
                1e-9);
  }
  EXPECT_EQ(wrong, 0) << "of " << n;
}

}  // namespace
}  // namespace curvsph
