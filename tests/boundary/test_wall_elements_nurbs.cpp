// Boundary elements of NURBS walls: exact lengths and areas, vertices and centres on the
// curve / surface, and the geometric Shepard factor on them against adaptive quadrature of W
// over the fluid region (tests/support/shepard_reference.hpp) at points approaching faces,
// edges and corners: wedges of degree-1 NURBS curves (2-D), a NURBS circle, and a tank corner
// whose floor is a NURBS bump (3-D).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <numeric>

#include "../support/shepard_reference.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/geometry/nurbs_surface_wall.hpp"

using namespace curvsph;

namespace {

constexpr double pi = std::numbers::pi;

template <int D>
double total_area(const BoundaryElements<D>& el) {
  return std::accumulate(el.area.begin(), el.area.end(), 0.0);
}

// gamma by the reference quadrature (shepard_geometric) and by the solver's evaluation
// (GeometricShepard over all elements); returns the larger error against `ref`.
template <int D>
double worst_error(const BoundaryElements<D>& el, const GeometricShepard<D>& fast, const VecD<D>& x,
                   double h, double ref) {
  std::vector<std::size_t> all(el.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  const double g1 = shepard_geometric<D>(el, x, h), g2 = fast(el, all, x);
  return std::max(std::abs(g1 - ref), std::abs(g2 - ref));
}

std::shared_ptr<NurbsCurveWall> wedge_curve(double alpha, double L, bool left) {
  // P0 -> apex -> P2, degree 1: the fluid of `left` is the wedge of opening alpha.
  nurbs::NurbsCurve<2> c(
      1, {Vec2d(L * std::cos(alpha), L * std::sin(alpha)), Vec2d(0, 0), Vec2d(L, 0)}, {},
      {0, 0, 1, 2, 2});
  return std::make_shared<NurbsCurveWall>(
      std::move(c), left ? NurbsCurveWall::Side::left : NurbsCurveWall::Side::right);
}

std::shared_ptr<NurbsCurveWall> nurbs_circle(const Vec2d& c, double R, bool inside) {
  // The rational quadratic circle of 9 control points (Piegl & Tiller §7.5), counter-clockwise.
  const double w = std::sqrt(0.5);
  std::vector<Vec2d> P;
  for (const auto& [x, y] :
       {std::pair{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}})
    P.push_back(c + R * Vec2d(x, y));
  nurbs::NurbsCurve<2> curve(2, P, {1, w, 1, w, 1, w, 1, w, 1},
                             {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1});
  return std::make_shared<NurbsCurveWall>(
      std::move(curve), inside ? NurbsCurveWall::Side::left : NurbsCurveWall::Side::right);
}

}  // namespace

TEST(NurbsCurveElements, WedgesOfDegreeOneApexFacesAndCorners) {
  const double h = 0.1, dx = 0.05, L = 1.0;
  double worst = 0;
  for (double deg : {60.0, 90.0, 135.0}) {
    const double alpha = deg * pi / 180;
    for (bool left : {true, false}) {
      const auto wall = wedge_curve(alpha, L, left);
      const auto el = elements_from_wall<2>(*wall, dx, {});
      EXPECT_NEAR(total_area(el), 2 * L, 1e-12);
      for (std::size_t j = 0; j < el.size(); ++j) {
        EXPECT_EQ(el.curvature[j], 0.0);
        EXPECT_EQ(el.gap[j], 0.0);
      }
      const GeometricShepard<2> fast(el, h);
      auto in_wedge = [alpha](const Vec2d& y) {
        return y[1] >= 0 && (std::sin(alpha) * y[0] - std::cos(alpha) * y[1]) >= 0;
      };
      auto fluid = [&](const Vec2d& y) { return left ? in_wedge(y) : !in_wedge(y); };
      // The apex: the opening angle over 2 pi, exactly.
      std::vector<std::size_t> all(el.size());
      std::iota(all.begin(), all.end(), std::size_t{0});
      const double apex = left ? alpha / (2 * pi) : 1 - alpha / (2 * pi);
      EXPECT_NEAR(shepard_geometric<2>(el, Vec2d(0, 0), h), apex, 1e-8) << deg;
      EXPECT_NEAR(fast(el, all, Vec2d(0, 0)), apex, 1e-8) << deg;
      // Points approaching a face, the apex along the bisector and along a face.
      const double s = left ? 1.0 : -1.0;
      const Vec2d bis = s * Vec2d(std::cos(alpha / 2), std::sin(alpha / 2));
      std::vector<Vec2d> pts;
      for (double d : {1.5, 1.0, 0.5, 0.2, 0.05, 0.0}) {
        pts.push_back(Vec2d(0.5, s * d * h));
        pts.push_back(d * h * bis);
        pts.push_back(Vec2d(d * h, s * 0.3 * h));
      }
      for (const Vec2d& x : pts) {
        if (!fluid(x)) continue;
        const double ref = test::reference_gamma_2d(x, h, fluid);
        const double e = worst_error<2>(el, fast, x, h, ref);
        worst = std::max(worst, e);
        EXPECT_LT(e, 0.005) << deg << " left " << left << " x " << x.transpose();
      }
    }
  }
  std::printf("degree-1 NURBS wedges 60/90/135 deg, both sides: max |gamma - ref| = %.2e\n", worst);
}

TEST(NurbsCurveElements, CircleLengthOnCurveAndGamma) {
  const double R = 0.4, h = 0.1, dx = 0.05;
  const Vec2d c(0.1, -0.2);
  double worst = 0;
  for (bool inside : {true, false}) {
    const auto wall = nurbs_circle(c, R, inside);
    const auto el = elements_from_wall<2>(*wall, dx, {});
    EXPECT_NEAR(total_area(el) / (2 * pi * R), 1.0, 1e-10);
    Vec2d closure = Vec2d::Zero();
    for (std::size_t j = 0; j < el.size(); ++j) {
      closure += el.normal[j] * el.area[j];
      EXPECT_NEAR((el.centre[j] - c).norm(), R, 1e-12);
      EXPECT_NEAR((el.vertices[j][0] - c).norm(), R, 1e-12);
      EXPECT_NEAR(el.normal[j].dot((el.centre[j] - c) / R), inside ? -1.0 : 1.0, 1e-12);
      EXPECT_NEAR(el.curvature[j], inside ? 1 / R : -1 / R, 1e-9);
    }
    EXPECT_LT(closure.norm(), 1e-10);
    const GeometricShepard<2> fast(el, h);
    auto fluid = [&](const Vec2d& y) { return inside ? (y - c).norm() <= R : (y - c).norm() >= R; };
    for (double t : {0.3, 1.9, 4.0}) {
      const Vec2d e(std::cos(t), std::sin(t));
      for (double d : {1.5, 1.0, 0.5, 0.2, 0.05, 0.0}) {
        const Vec2d x = c + (inside ? R - d * h : R + d * h) * e;
        const double ref = test::reference_gamma_2d(x, h, fluid);
        const double err = worst_error<2>(el, fast, x, h, ref);
        worst = std::max(worst, err);
        EXPECT_LT(err, 0.005) << "inside " << inside << " t " << t << " d " << d;
      }
    }
  }
  std::printf("NURBS circle, inside and outside: max |gamma - ref| = %.2e\n", worst);
}

namespace {

// Clamped uniform knots of degree p for n control points on [0, 1].
std::vector<double> clamped(int p, int n) {
  std::vector<double> U(static_cast<std::size_t>(p + 1), 0.0);
  for (int k = 1; k < n - p; ++k) U.push_back(double(k) / (n - p));
  U.insert(U.end(), static_cast<std::size_t>(p + 1), 1.0);
  return U;
}

// Bilinear patch p00 + u (p10 - p00) + v (p01 - p00) (fluid on the side of e_u x e_v).
std::shared_ptr<NurbsSurfaceWall> flat_patch(const Vec3d& p00, const Vec3d& eu, const Vec3d& ev) {
  nurbs::NurbsSurface s(1, 1, {{p00, p00 + ev}, {p00 + eu, p00 + eu + ev}}, {}, {0, 0, 1, 1},
                        {0, 0, 1, 1});
  return std::make_shared<NurbsSurfaceWall>(std::move(s), NurbsSurfaceWall::Side::front);
}

}  // namespace

TEST(NurbsSurfaceElements, BumpTankFacesEdgesAndCorner) {
  // Floor z = Z(x, y) on [0, L]^2, a bicubic B-spline with control points at the Greville
  // abscissae in x and y (so x = L u, y = L v exactly: linear precision) and heights
  // A sin(pi xi) sin(pi eta); walls x = 0 and y = 0 as bilinear NURBS patches. The fluid is
  // above the floor and at x, y > 0: edges of varying dihedral angle (below 90 deg where the
  // floor rises from a wall) and a corner at the origin.
  const double L = 1.2, H = 0.8, A = 0.25, h = 0.1, dx = 0.05;
  const int p = 3, n = 8;
  const std::vector<double> U = clamped(p, n);
  std::vector<double> xi(n);
  for (int i = 0; i < n; ++i) xi[i] = (U[i + 1] + U[i + 2] + U[i + 3]) / 3;
  std::vector<std::vector<Vec3d>> ctrl(n, std::vector<Vec3d>(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      ctrl[i][j] = Vec3d(L * xi[i], L * xi[j], A * std::sin(pi * xi[i]) * std::sin(pi * xi[j]));
  auto floor = std::make_shared<NurbsSurfaceWall>(nurbs::NurbsSurface(p, p, ctrl, {}, U, U),
                                                  NurbsSurfaceWall::Side::front);
  const nurbs::NurbsSurface& S = floor->surface();
  ASSERT_NEAR(S.point(0.37, 0.81).x(), L * 0.37, 1e-12);
  ASSERT_NEAR(S.point(0.37, 0.81).y(), L * 0.81, 1e-12);
  auto Z = [&](double X, double Y) {
    return S.point(std::clamp(X / L, 0.0, 1.0), std::clamp(Y / L, 0.0, 1.0)).z();
  };
  WallSet<3> walls;
  walls.add(floor);
  walls.add(flat_patch(Vec3d(0, 0, 0), Vec3d(0, L, 0), Vec3d(0, 0, H)));  // x = 0
  walls.add(flat_patch(Vec3d(0, 0, 0), Vec3d(0, 0, H), Vec3d(L, 0, 0)));  // y = 0
  const auto fl = elements_from_wall<3>(*walls.walls()[0], dx, {});
  const auto el = elements_from_walls<3>(walls, dx, {});
  // Floor area against an independent midpoint rule of sqrt(1 + Zx^2 + Zy^2) (central
  // differences of the height field); the walls are L x H each.
  const int m = 600;
  const double hx = L / m, e = 1e-5;
  double area = 0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const double X = (i + 0.5) * hx, Y = (j + 0.5) * hx;
      const double zx = (Z(X + e, Y) - Z(X - e, Y)) / (2 * e),
                   zy = (Z(X, Y + e) - Z(X, Y - e)) / (2 * e);
      area += std::sqrt(1 + zx * zx + zy * zy) * hx * hx;
    }
  EXPECT_NEAR(total_area(fl) / area, 1.0, 2e-6);
  EXPECT_NEAR(total_area(el) - total_area(fl), 2 * L * H, 1e-12);
  for (std::size_t j = 0; j < fl.size(); ++j) {
    for (int k = 0; k < fl.vertex_count[j]; ++k) {
      const Vec3d& v = fl.vertices[j][static_cast<std::size_t>(k)];
      EXPECT_NEAR(v.z(), Z(v.x(), v.y()), 1e-12);
    }
    EXPECT_NEAR(fl.centre[j].z(), Z(fl.centre[j].x(), fl.centre[j].y()), 1e-12);
    EXPECT_GT(fl.normal[j].z(), 0.5);  // into the fluid, above the floor
  }
  const GeometricShepard<3> fast(el, h);
  const test::Columns fluid = [&](double X, double Y) {
    std::vector<std::pair<double, double>> out;
    if (X > 0 && Y > 0) out.push_back({Z(X, Y), 1e300});
    return out;
  };
  auto normal_at = [&](double X, double Y) {
    const nurbs::SurfaceDerivs d = S.eval(X / L, Y / L);
    return Vec3d(d.su.cross(d.sv).normalized());
  };
  struct Probe {
    const char* what;
    Vec3d base, dir;
  };
  const Vec3d edge(0, 0.5, 0);
  const std::vector<Probe> probes = {
      {"floor top", Vec3d(0.6, 0.6, Z(0.6, 0.6)), normal_at(0.6, 0.6)},
      {"floor slope", Vec3d(0.35, 0.5, Z(0.35, 0.5)), normal_at(0.35, 0.5)},
      {"floor-wall edge", edge, (normal_at(0, 0.5) + Vec3d(1, 0, 0)).normalized()},
      {"corner", Vec3d(0, 0, 0), Vec3d(1, 1, 1).normalized()},
      {"wall-wall edge", Vec3d(0, 0, 0.3), Vec3d(1, 1, 0).normalized()}};
  double worst = 0;
  for (const Probe& pr : probes) {
    double worst_here = 0;
    // Down to 1e-6 h: points that close to an edge lie behind the floor's non-planar quads
    // by more than their distance to the wall (the on-wall band, geometric_impl).
    for (double d : {1.5, 1.0, 0.5, 0.2, 0.05, 1e-3, 1e-6, 0.0}) {
      const Vec3d x = pr.base + d * h * pr.dir;
      const double ref = test::reference_gamma_3d(x, h, fluid);
      const double err = worst_error<3>(el, fast, x, h, ref);
      worst_here = std::max(worst_here, err);
      EXPECT_LT(err, 0.005) << pr.what << " d/h " << d << " ref " << ref;
    }
    std::printf("NURBS bump tank, %s: max |gamma - ref| = %.2e\n", pr.what, worst_here);
    worst = std::max(worst, worst_here);
  }
  std::printf("NURBS bump tank: max |gamma - ref| = %.2e over %zu elements\n", worst, el.size());
}

TEST(ShepardReference3D, FlatWallColumns) {
  // The column reference itself against the radial closed form for a half-space.
  const double h = 0.1;
  const WendlandC2<3> W(h);
  for (double d : {0.0, 0.05, 0.13}) {
    const double ref =
        1.0 -
        gauss_legendre_8([&](double r) { return W.value(r) * 2 * pi * r * (r - d); }, d, 2 * h, 8);
    const test::Columns half = [](double, double) {
      return std::vector<std::pair<double, double>>{{0.0, 1e300}};
    };
    EXPECT_NEAR(test::reference_gamma_3d(Vec3d(0.01, 0.02, d), h, half), ref, 2e-6) << d;
  }
}
