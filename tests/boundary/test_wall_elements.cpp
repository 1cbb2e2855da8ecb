// Boundary elements from walls: exact lengths / areas, closed walls with zero total n dA,
// normals that follow the curved wall, and the geometric Shepard factor on these elements
// (1 far inside, the exact on-wall value on the wall).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/core/quadrature.hpp"
#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/ellipse.hpp"
#include "curvsph/geometry/plane.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/torus.hpp"
#include "curvsph/kernels/wendland.hpp"

using namespace curvsph;

namespace {

constexpr double pi = std::numbers::pi;

template <int D>
double total_area(const BoundaryElements<D>& el) {
  double s = 0;
  for (double a : el.area) s += a;
  return s;
}

template <int D>
double total_normal_area(const BoundaryElements<D>& el) {
  VecD<D> s = VecD<D>::Zero();
  for (std::size_t j = 0; j < el.size(); ++j) s += el.normal[j] * el.area[j];
  return s.norm();
}

template <int D>
WallSet<D> single(WallPtr<D> w) {
  WallSet<D> s;
  s.add(std::move(w));
  return s;
}

// gamma on a circle (2-D) / sphere (3-D) of radius R for a point on it: the fraction of each
// kernel shell |y - x| = r inside, exactly (fluid inside: arccos(r/2R)/pi in 2-D,
// 1/2 - r/(4R) in 3-D), integrated over r with 8-point Gauss-Legendre on 16 pieces.
template <int D>
double on_wall_reference(double h, double R, bool inside) {
  const auto& xg = kGaussLegendre8Nodes;
  const auto& wg = kGaussLegendre8Weights;
  const WendlandC2<D> W(h);
  double sum = 0;
  const int pieces = 16;
  const double w = 2 * h / pieces;
  for (int p = 0; p < pieces; ++p)
    for (int i = 0; i < 8; ++i) {
      const double r = (p + 0.5) * w + 0.5 * w * xg[i];
      double frac, shell;
      if constexpr (D == 2) {
        frac = std::acos(r / (2 * R)) / pi;
        shell = 2 * pi * r;
      } else {
        frac = 0.5 - r / (4 * R);
        shell = 4 * pi * r * r;
      }
      if (!inside) frac = 1 - frac;
      sum += 0.5 * w * wg[i] * W.value(r) * shell * frac;
    }
  return sum;
}

}  // namespace

TEST(BoundaryElements2D, CircleLengthAndClosure) {
  for (auto side : {FluidSide::inside, FluidSide::outside}) {
    const double R = 1.3;
    const auto el = elements_from_walls<2>(
        single<2>(std::make_shared<CircleWall>(Vec2d(0.2, -0.1), R, side)), 0.05, {});
    EXPECT_NEAR(total_area(el) / (2 * pi * R), 1.0, 1e-10);
    EXPECT_LT(total_normal_area(el), 1e-12);
    for (std::size_t j = 0; j < el.size(); ++j) {
      const Vec2d out = (el.centre[j] - Vec2d(0.2, -0.1)).normalized();
      EXPECT_NEAR(el.normal[j].dot(out), side == FluidSide::inside ? -1.0 : 1.0, 1e-12);
    }
  }
}

TEST(BoundaryElements2D, EllipseArcLengthNormalsAndClosure) {
  const double a = 2.0, b = 0.7;
  // Independent perimeter: the trapezoid rule on the periodic |C'| (spectrally accurate).
  const int n = 20000;
  double perimeter = 0;
  for (int k = 0; k < n; ++k) {
    const double u = 2 * pi * k / n;
    perimeter += std::hypot(a * std::sin(u), b * std::cos(u)) * 2 * pi / n;
  }
  for (auto side : {FluidSide::inside, FluidSide::outside}) {
    const Vec2d c(0.5, 0.25);
    const auto el =
        elements_from_walls<2>(single<2>(std::make_shared<EllipseWall>(c, a, b, side)), 0.04, {});
    EXPECT_NEAR(total_area(el) / perimeter, 1.0, 1e-10);
    EXPECT_LT(total_normal_area(el), 1e-10 * perimeter);
    const double mean = perimeter / el.size();
    for (std::size_t j = 0; j < el.size(); ++j) {
      EXPECT_NEAR(el.area[j], mean, 1e-9 * mean);  // equal arc lengths
      auto on = [&](const Vec2d& p) {
        const Vec2d q = p - c;
        return q.x() * q.x() / (a * a) + q.y() * q.y() / (b * b) - 1.0;
      };
      EXPECT_NEAR(on(el.centre[j]), 0.0, 1e-12);
      EXPECT_NEAR(on(el.vertices[j][0]), 0.0, 1e-12);
      // The normal is the ellipse's gradient at the centre (not the chord's normal).
      const Vec2d q = el.centre[j] - c;
      const Vec2d grad = Vec2d(q.x() / (a * a), q.y() / (b * b)).normalized();
      EXPECT_NEAR(el.normal[j].dot(grad), side == FluidSide::inside ? -1.0 : 1.0, 1e-12);
      EXPECT_GE(el.gap[j], 0.0);
      EXPECT_LT(el.gap[j], 1e-2 * mean);  // O(dx^3) for the arc through 3 points
    }
  }
}

TEST(BoundaryElements2D, BoxAndClippedPlane) {
  const auto box = elements_from_walls<2>(
      single<2>(std::make_shared<BoxWall<2>>(Vec2d(0, 0), Vec2d(2, 1), FluidSide::inside)), 0.1,
      {});
  EXPECT_NEAR(total_area(box), 6.0, 1e-12);
  EXPECT_LT(total_normal_area(box), 1e-12);
  EXPECT_GT(box.normal[0].y(), 0.99);  // bottom side: the fluid is above
  const Bounds<2> domain(Vec2d(-1, -1), Vec2d(3, 2));
  const auto plane = elements_from_walls<2>(
      single<2>(std::make_shared<PlaneWall<2>>(Vec2d(0, 0.5), Vec2d(0, 1))), 0.1, domain);
  EXPECT_NEAR(total_area(plane), 4.0, 1e-12);
  for (std::size_t j = 0; j < plane.size(); ++j) EXPECT_NEAR(plane.normal[j].y(), 1.0, 1e-15);
  const auto oblique = elements_from_walls<2>(
      single<2>(std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(-1, 1))), 0.1, domain);
  EXPECT_NEAR(total_area(oblique), 3 * std::sqrt(2.0), 1e-12);  // (-1,-1) .. (2,2)
  EXPECT_THROW(elements_from_walls<2>(
                   single<2>(std::make_shared<PlaneWall<2>>(Vec2d(0, 0), Vec2d(0, 1))), 0.1, {}),
               std::invalid_argument);
}

TEST(BoundaryElements3D, SphereTorusCylinderAreas) {
  const double R = 1.2;
  for (auto side : {FluidSide::inside, FluidSide::outside}) {
    const Vec3d c(0.1, 0.2, -0.3);
    const auto s =
        elements_from_walls<3>(single<3>(std::make_shared<SphereWall>(c, R, side)), 0.1, {});
    EXPECT_NEAR(total_area(s) / (4 * pi * R * R), 1.0, 1e-10);
    EXPECT_LT(total_normal_area(s), 1e-10);
    for (std::size_t j = 0; j < s.size(); ++j) {
      EXPECT_NEAR((s.centre[j] - c).norm(), R, 1e-12);
      EXPECT_NEAR(s.normal[j].dot((s.centre[j] - c) / R), side == FluidSide::inside ? -1 : 1,
                  1e-12);
      for (int k = 0; k < s.vertex_count[j]; ++k)
        EXPECT_NEAR((s.vertices[j][static_cast<std::size_t>(k)] - c).norm(), R, 1e-12);
    }
  }
  const double Rt = 1.0, a = 0.3;
  const auto t =
      elements_from_walls<3>(single<3>(std::make_shared<TorusWall>(Vec3d(0, 0, 0), Vec3d(1, 1, 0),
                                                                   Rt, a, FluidSide::inside)),
                             0.05, {});
  EXPECT_NEAR(total_area(t) / (4 * pi * pi * Rt * a), 1.0, 1e-10);
  EXPECT_LT(total_normal_area(t), 1e-10);
  const Bounds<3> domain(Vec3d(-2, -2, 0.5), Vec3d(2, 2, 2.5));
  const auto cyl =
      elements_from_walls<3>(single<3>(std::make_shared<CylinderWall>(
                                 Vec3d(0, 0, 0), Vec3d(0, 0, 1), 0.5, FluidSide::outside)),
                             0.05, domain);
  EXPECT_NEAR(total_area(cyl) / (2 * pi * 0.5 * 2.0), 1.0, 1e-10);
  for (std::size_t j = 0; j < cyl.size(); ++j) {
    EXPECT_GE(cyl.centre[j].z(), 0.5);
    EXPECT_LE(cyl.centre[j].z(), 2.5);
  }
}

TEST(BoundaryElements3D, BoxFacesAndClippedPlane) {
  for (auto side : {FluidSide::inside, FluidSide::outside}) {
    const auto box = elements_from_walls<3>(
        single<3>(std::make_shared<BoxWall<3>>(Vec3d(0, 0, 0), Vec3d(1, 2, 0.5), side)), 0.1, {});
    EXPECT_NEAR(total_area(box), 2 * (2 + 0.5 + 1), 1e-12);
    EXPECT_LT(total_normal_area(box), 1e-12);
    for (std::size_t j = 0; j < box.size(); ++j) {
      const Vec3d to_centre = Vec3d(0.5, 1, 0.25) - box.centre[j];
      EXPECT_EQ(box.normal[j].dot(to_centre) > 0, side == FluidSide::inside);
    }
  }
  const Bounds<3> domain(Vec3d(-1, 0, 0), Vec3d(1, 3, 2));
  const auto plane = elements_from_walls<3>(
      single<3>(std::make_shared<PlaneWall<3>>(Vec3d(0, 0, 1), Vec3d(0, 0, -1))), 0.1, domain);
  EXPECT_NEAR(total_area(plane), 6.0, 1e-12);
  for (std::size_t j = 0; j < plane.size(); ++j) EXPECT_NEAR(plane.normal[j].z(), -1.0, 1e-15);
}

TEST(BoundaryElementsShepard, ClosedCircleAndEllipse) {
  const double R = 1.0, h = 0.02, dx = 0.01;
  for (auto side : {FluidSide::inside, FluidSide::outside}) {
    const auto el = elements_from_walls<2>(
        single<2>(std::make_shared<CircleWall>(Vec2d(0, 0), R, side)), dx, {});
    const bool in = side == FluidSide::inside;
    EXPECT_NEAR(shepard_geometric<2>(el, Vec2d(in ? 0.1 : 2.0, 0.2), h), 1.0, 1e-12);
    const double ref = on_wall_reference<2>(h, R, in);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(-pi, pi);
    for (int k = 0; k < 20; ++k) {
      const double t = angle(rng);
      const double g = shepard_geometric<2>(el, Vec2d(R * std::cos(t), R * std::sin(t)), h);
      EXPECT_NEAR(g, ref, 2e-3) << "angle " << t;
      EXPECT_NEAR(g, 0.5, 0.005);
    }
  }
  // Ellipse: points on the true curve (between element vertices: within the elements' gap).
  const double a = 1.0, b = 0.6, he = 0.005;
  const auto el = elements_from_walls<2>(
      single<2>(std::make_shared<EllipseWall>(Vec2d(0, 0), a, b, FluidSide::inside)), he / 2, {});
  EXPECT_NEAR(shepard_geometric<2>(el, Vec2d(0.3, 0.1), he), 1.0, 1e-12);
  for (int k = 0; k < 24; ++k) {
    const double u = 0.1 + 2 * pi * k / 24;
    EXPECT_NEAR(shepard_geometric<2>(el, Vec2d(a * std::cos(u), b * std::sin(u)), he), 0.5, 0.005)
        << "u " << u;
  }
}

TEST(BoundaryElementsShepard, ClosedSphereAndBox) {
  const double R = 1.0, h = 0.1, dx = 0.05;
  const auto el = elements_from_walls<3>(
      single<3>(std::make_shared<SphereWall>(Vec3d(0, 0, 0), R, FluidSide::inside)), dx, {});
  EXPECT_NEAR(shepard_geometric<3>(el, Vec3d(0.1, -0.2, 0.3), h), 1.0, 1e-12);
  const double ref = on_wall_reference<3>(h, R, true);
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0, 1);
  for (int k = 0; k < 12; ++k) {
    const Vec3d p = Vec3d(g(rng), g(rng), g(rng)).normalized() * R;  // on the true sphere
    EXPECT_NEAR(shepard_geometric<3>(el, p, h), ref, 0.005) << p.transpose();
  }
  // The points where the elements touch the sphere exactly: the vertices.
  for (std::size_t j = 0; j < el.size(); j += el.size() / 7)
    EXPECT_NEAR(shepard_geometric<3>(el, el.vertices[j][1], h), ref, 0.005);

  const auto box = elements_from_walls<3>(
      single<3>(std::make_shared<BoxWall<3>>(Vec3d(0, 0, 0), Vec3d(1, 1, 1), FluidSide::inside)),
      dx, {});
  EXPECT_NEAR(shepard_geometric<3>(box, Vec3d(0.5, 0.45, 0.55), h), 1.0, 1e-12);
  for (const Vec3d& p : {Vec3d(0.5, 0.5, 0), Vec3d(0.33, 1, 0.61), Vec3d(1, 0.27, 0.4)})
    EXPECT_NEAR(shepard_geometric<3>(box, p, h), 0.5, 0.005) << p.transpose();
}
