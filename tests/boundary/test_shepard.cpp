#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "../support/shepard_reference.hpp"
#include "curvsph/boundary/integrals/boundary_elements.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/core/quadrature.hpp"
#include "curvsph/kernels/wendland.hpp"

using namespace curvsph;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double h = 1.0;
constexpr double dx = 0.5;  // h/dx = 2

// ---- Independent reference: gamma(x) = int over the fluid part of the support disc of W
// (tests/support/shepard_reference.hpp: polar coordinates about x, adaptive in the angle).
double reference_gamma(const Vec2d& x, const std::function<bool(const Vec2d&)>& inside) {
  return test::reference_gamma_2d(x, h, inside);
}

// ---- Geometries (fluid region predicates and elements at spacing dx).
bool upper_half(const Vec2d& y) {
  return y[1] >= 0;
}
BoundaryElements<2> flat_wall() {
  return polyline_elements({{-6, 0}, {6, 0}}, dx);
}

std::function<bool(const Vec2d&)> wedge(double alpha) {
  return [alpha](const Vec2d& y) {
    return y[1] >= 0 && (std::sin(alpha) * y[0] - std::cos(alpha) * y[1]) >= 0;
  };
}
BoundaryElements<2> wedge_walls(double alpha, double L = 6) {
  return polyline_elements({{L * std::cos(alpha), L * std::sin(alpha)}, {0, 0}, {L, 0}}, dx);
}

}  // namespace

TEST(ShepardReference, DesignFlatWallValues) {
  // The reference quadrature itself against DESIGN.md §4 (and an independent mpmath check).
  EXPECT_NEAR(reference_gamma({0.3, 0.1}, upper_half), 0.573815, 2e-6);
  EXPECT_NEAR(reference_gamma({0.0, 0.5}, upper_half), 0.823497, 2e-6);
  EXPECT_NEAR(reference_gamma({0.0, 1.0}, upper_half), 0.971491, 2e-6);
}

TEST(ShepardGeometric, FarFromWallsIsOne) {
  EXPECT_NEAR(shepard_geometric<2>(flat_wall(), Vec2d(0, 2.0001), h), 1.0, 1e-10);
  EXPECT_DOUBLE_EQ(shepard_geometric<2>(flat_wall(), Vec2d(0, 2.6), h), 1.0);
  EXPECT_NEAR(shepard_geometric<2>(flat_wall(), Vec2d(0.1, 1.9999), h), 1.0, 1e-10);
}

TEST(ShepardGeometric, FlatWallDesignValues) {
  const auto el = flat_wall();
  EXPECT_NEAR(shepard_geometric<2>(el, Vec2d(0.0, 0.0), h), 0.5, 1e-8);
  EXPECT_NEAR(shepard_geometric<2>(el, Vec2d(0.25, 0.0), h), 0.5, 1e-8);
  EXPECT_NEAR(shepard_geometric<2>(el, Vec2d(0.1, 0.1), h), 0.573815, 1e-5);
  EXPECT_NEAR(shepard_geometric<2>(el, Vec2d(0.0, 0.5), h), 0.823497, 1e-5);
  EXPECT_NEAR(shepard_geometric<2>(el, Vec2d(0.37, 1.0), h), 0.971491, 1e-5);
}

TEST(ShepardGeometric, FlatWallApproach) {
  const auto el = flat_wall();
  for (double x0 : {0.0, 0.25, 0.1}) {
    for (int k = 0; k <= 40; ++k) {
      const Vec2d x(x0, 2 * h * (1 - k / 40.0));
      EXPECT_NEAR(shepard_geometric<2>(el, x, h), reference_gamma(x, upper_half), 0.005)
          << x.transpose();
    }
  }
}

TEST(ShepardGeometric, CornerApexAngles) {
  EXPECT_NEAR(shepard_geometric<2>(wedge_walls(pi / 2), Vec2d(0, 0), h), 0.25, 1e-8);
  EXPECT_NEAR(shepard_geometric<2>(wedge_walls(pi / 3), Vec2d(0, 0), h), 1.0 / 6, 1e-8);
  EXPECT_NEAR(shepard_geometric<2>(wedge_walls(2 * pi / 3), Vec2d(0, 0), h), 1.0 / 3, 1e-8);
}

TEST(ShepardGeometric, CornerApproachSideAndDiagonal) {
  const auto el = wedge_walls(pi / 2);
  const auto in = wedge(pi / 2);
  for (int k = 0; k <= 30; ++k) {
    const double t = 3 * h * (1 - k / 30.0);
    for (const Vec2d& x : {Vec2d(t, 0), Vec2d(t, 0.5 * dx), Vec2d(Vec2d(t, t) / std::sqrt(2.0))}) {
      EXPECT_NEAR(shepard_geometric<2>(el, x, h), reference_gamma(x, in), 0.005) << x.transpose();
    }
  }
}

TEST(ShepardGeometric, CircleApproachInsideAndOutside) {
  const double R = 4 * h;
  for (bool inside : {true, false}) {
    for (double start : {0.0, 0.5 * dx / R}) {
      const auto el = circle_elements(Vec2d(0, 0), R, dx, inside, start);
      auto region = [&](const Vec2d& y) { return inside ? y.norm() <= R : y.norm() >= R; };
      for (int k = 0; k <= 30; ++k) {
        const double d = 2 * h * (1 - k / 30.0);
        const Vec2d x(inside ? R - d : R + d, 0);
        EXPECT_NEAR(shepard_geometric<2>(el, x, h), reference_gamma(x, region), 0.005)
            << "inside " << inside << " d " << d;
      }
    }
  }
}

TEST(ShepardGeometric, SubtendedAnglesCloseAroundInteriorPoints) {
  const auto poly = polyline_elements({{0, 0}, {3, 0}, {3, 2}, {0, 2}}, dx, true);
  const auto circ = circle_elements(Vec2d(1, 1), 2.0, 0.3, true);
  for (const Vec2d& x : {Vec2d(1, 1), Vec2d(2.9, 0.05)}) {
    double s1 = 0, s2 = 0;
    const Vec2d xc = Vec2d(1, 1) + 0.99 * (x - Vec2d(1, 1)).normalized() *
                                       ((x - Vec2d(1, 1)).norm() > 0 ? 2.0 : 0.0);
    for (std::size_t j = 0; j < poly.size(); ++j) s1 += subtended_angle<2>(poly, j, x);
    for (std::size_t j = 0; j < circ.size(); ++j) s2 += subtended_angle<2>(circ, j, xc);
    EXPECT_NEAR(s1, 2 * pi, 1e-12);
    EXPECT_NEAR(s2, 2 * pi, 1e-12);
  }
  // Outside a closed wall the angles cancel.
  double s = 0;
  for (std::size_t j = 0; j < poly.size(); ++j) s += subtended_angle<2>(poly, j, Vec2d(5, 1));
  EXPECT_NEAR(s, 0.0, 1e-12);
  // 3-D: a closed cube subtends 4 pi at an interior point (fluid inside).
  BoundaryElements<3> cube;
  const Vec3d o(0, 0, 0);
  const Vec3d ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
  cube.append(rectangle_elements(o, ex, ey, 0.25));       // z = 0, normal +z
  cube.append(rectangle_elements(o + ez, ey, ex, 0.25));  // z = 1, normal -z
  cube.append(rectangle_elements(o, ez, ex, 0.25));       // y = 0, normal +y
  cube.append(rectangle_elements(o + ey, ex, ez, 0.25));  // y = 1, normal -y
  cube.append(rectangle_elements(o, ey, ez, 0.25));       // x = 0, normal +x
  cube.append(rectangle_elements(o + ex, ez, ey, 0.25));  // x = 1, normal -x
  double omega = 0;
  for (std::size_t j = 0; j < cube.size(); ++j)
    omega += subtended_angle<3>(cube, j, Vec3d(0.3, 0.6, 0.2));
  EXPECT_NEAR(omega, 4 * pi, 1e-10);
}

namespace {
// 3-D flat wall reference: 1 - int_{z < -d} W = 1 - int_d^2h W(r) 2 pi r (r - d) dr.
double reference_flat_3d(double d) {
  const WendlandC2<3> W(h);
  const int n = 20000;
  double s = 0;
  for (int k = 0; k < n; ++k) {  // midpoint rule, smooth integrand
    const double r = d + (2 * h - d) * (k + 0.5) / n;
    s += W.value(r) * 2 * pi * r * (r - d);
  }
  return 1 - s * (2 * h - d) / n;
}
}  // namespace

TEST(ShepardGeometric3D, FlatWallAndCorner) {
  const double L = 3.0;
  const auto plane =
      rectangle_elements(Vec3d(-L, -L, 0), Vec3d(2 * L, 0, 0), Vec3d(0, 2 * L, 0), dx);
  EXPECT_NEAR(shepard_geometric<3>(plane, Vec3d(0, 0, 0), h), 0.5, 1e-8);
  EXPECT_NEAR(shepard_geometric<3>(plane, Vec3d(0.1, 0.25, 0), h), 0.5, 1e-8);
  EXPECT_NEAR(reference_flat_3d(0.5), 0.827583312988281, 1e-8);
  EXPECT_NEAR(shepard_geometric<3>(plane, Vec3d(0.1, 0.2, 0.5), h), reference_flat_3d(0.5), 1e-3);
  EXPECT_NEAR(shepard_geometric<3>(plane, Vec3d(0.0, 0.0, 1.2), h), reference_flat_3d(1.2), 1e-3);
  EXPECT_NEAR(shepard_geometric<3>(plane, Vec3d(0.0, 0.0, 2.01), h), 1.0, 1e-10);

  // Three faces meeting at the origin, fluid in the positive octant.
  BoundaryElements<3> corner;
  corner.append(rectangle_elements(Vec3d(0, 0, 0), Vec3d(L, 0, 0), Vec3d(0, L, 0), dx));
  corner.append(rectangle_elements(Vec3d(0, 0, 0), Vec3d(0, L, 0), Vec3d(0, 0, L), dx));
  corner.append(rectangle_elements(Vec3d(0, 0, 0), Vec3d(0, 0, L), Vec3d(L, 0, 0), dx));
  EXPECT_NEAR(shepard_geometric<3>(corner, Vec3d(0, 0, 0), h), 0.125, 1e-8);
  // On an edge far from the apex: a 90 degree dihedral, gamma = 1/4.
  EXPECT_NEAR(shepard_geometric<3>(corner, Vec3d(2.5, 0, 0), h), 0.25, 2e-3);
  // Triangles give the same as quads on a plane.
  std::vector<std::array<Vec3d, 3>> tris;
  for (std::size_t j = 0; j < plane.size(); ++j) {
    const auto& v = plane.vertices[j];
    tris.push_back({v[0], v[1], v[2]});
    tris.push_back({v[0], v[2], v[3]});
  }
  EXPECT_NEAR(shepard_geometric<3>(triangle_elements(tris), Vec3d(0.1, 0.2, 0.5), h),
              reference_flat_3d(0.5), 1e-3);
}

TEST(ShepardModes, ParseMonolithicVolumeNone) {
  EXPECT_EQ(shepard_mode_from_string("geometric"), ShepardMode::geometric);
  EXPECT_EQ(shepard_mode_from_string("volume"), ShepardMode::volume);
  EXPECT_STREQ(to_string(ShepardMode::monolithic), "monolithic");
  EXPECT_THROW(shepard_mode_from_string("Geometric"), std::invalid_argument);
  const auto el = flat_wall();
  EXPECT_DOUBLE_EQ(shepard_monolithic<2>(el, Vec2d(0, 2.5), h), 1.0);
  EXPECT_NEAR(shepard_monolithic<2>(el, Vec2d(0.1, 1.0), h), 0.971491, 5e-3);
  // Volume mode on a lattice: ~1 in the bulk, ~1/2 at the wall.
  std::vector<Vec2d> pos;
  std::vector<double> vol;
  for (int i = -16; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      pos.emplace_back((i + 0.5) * dx, (j + 0.5) * dx);
      vol.push_back(dx * dx);
    }
  EXPECT_NEAR(shepard_volume<2>(pos, vol, Vec2d(0, 4), h), 1.0, 2e-3);
  EXPECT_NEAR(shepard_volume<2>(pos, vol, Vec2d(0, 0), h), 0.5, 2e-2);
  const std::vector<Vec2d> pts{{0, 4}, {0, 0}};
  const auto g = shepard_factor<2>(ShepardMode::none, el, pts, h);
  EXPECT_EQ(g, (std::vector<double>{1.0, 1.0}));
  const auto gg = shepard_factor<2>(ShepardMode::geometric, el, pts, h);
  EXPECT_NEAR(gg[1], 0.5, 1e-8);
}

// ---- GeometricShepard (the solver's path) against shepard_geometric over all elements: a
// tank corner with a box obstacle on its floor (flat faces: twins cancel) and a sphere
// (curved patches: no twins). Points near walls, on walls, at edges and apexes.
namespace {

BoundaryElements<3> tank_and_box() {
  BoundaryElements<3> el;
  const double L = 4.0;
  // Floor z = 0, walls x = 0 and y = 0 (fluid in the positive octant).
  el.append(rectangle_elements(Vec3d(0, 0, 0), Vec3d(L, 0, 0), Vec3d(0, L, 0), dx));
  el.append(rectangle_elements(Vec3d(0, 0, 0), Vec3d(0, L, 0), Vec3d(0, 0, L), dx));
  el.append(rectangle_elements(Vec3d(0, 0, 0), Vec3d(0, 0, L), Vec3d(L, 0, 0), dx));
  // Obstacle [1.5, 2.5] x [1.5, 2.5] x [0, 1]: its four sides and top (normals outward).
  el.append(rectangle_elements(Vec3d(1.5, 1.5, 1), Vec3d(1, 0, 0), Vec3d(0, 1, 0), dx));
  el.append(rectangle_elements(Vec3d(2.5, 1.5, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1), dx));
  el.append(rectangle_elements(Vec3d(1.5, 1.5, 0), Vec3d(0, 0, 1), Vec3d(0, 1, 0), dx));
  el.append(rectangle_elements(Vec3d(1.5, 2.5, 0), Vec3d(0, 0, 1), Vec3d(1, 0, 0), dx));
  el.append(rectangle_elements(Vec3d(1.5, 1.5, 0), Vec3d(1, 0, 0), Vec3d(0, 0, 1), dx));
  return el;
}

std::vector<Vec3d> probe_points() {
  std::vector<Vec3d> pts = {{0, 0, 0},       {1, 0, 0},       {0.3, 0.2, 0.1}, {1.5, 1.5, 1},
                            {2.5, 2, 0.5},   {2.6, 2, 0.05},  {1, 1, 1e-3},    {2, 2, 1.2},
                            {3.5, 3.5, 2.5}, {1.5, 1.5, 0.0}, {0.25, 0.25, 0}, {2.51, 1.49, 0.3}};
  // The rim path of GeometricShepard<3>: feet outside the faces they are cut by (beside and
  // above the box's top edge and corner), three faces cut at once (the tank corner), and feet
  // on a rim edge and a rim corner of the floor (x = 4 and y = 4 have no wall), which go to
  // the element path.
  for (const Vec3d& p : {Vec3d(2.6, 2.0, 1.05), Vec3d(1.45, 1.45, 1.02), Vec3d(2.55, 2.55, 0.5),
                         Vec3d(0.1, 0.1, 0.1), Vec3d(0.05, 3.9, 0.3), Vec3d(2.0, 2.0, 1.3),
                         Vec3d(4.0, 2.0, 0.5), Vec3d(4.0, 4.0, 0.7), Vec3d(4.3, 2.0, 0.5)})
    pts.push_back(p);
  unsigned s = 12345;
  auto rnd = [&] {
    s = s * 1103515245u + 12345u;
    return ((s >> 8) & 0xffff) / 65535.0;
  };
  for (int k = 0; k < 40; ++k) {
    const Vec3d x(3.5 * rnd(), 3.5 * rnd(), 2.5 * rnd());
    const bool in_box = x[0] > 1.5 && x[0] < 2.5 && x[1] > 1.5 && x[1] < 2.5 && x[2] < 1;
    if (!in_box) pts.push_back(x);
  }
  return pts;
}

}  // namespace

TEST(GeometricShepardFast, MatchesBruteForceOnFlatWalls) {
  const auto el = tank_and_box();
  const GeometricShepard<3> fast(el, h);
  ShepardQuadrature fine;  // the brute-force path with 8 Gauss points on pieces <= h/8
  fine.gauss_points = 8;
  fine.max_piece_over_h = 0.125;
  std::vector<std::size_t> all(el.size());
  for (std::size_t j = 0; j < all.size(); ++j) all[j] = j;
  double worst_default = 0, worst_fine = 0;
  for (const Vec3d& x : probe_points()) {
    const double g_fast = fast(el, all, x);
    const double g_brute = shepard_geometric<3>(el, x, h);
    const double g_fine = shepard_geometric<3>(el, x, h, fine);
    worst_default = std::max(worst_default, std::abs(g_fast - g_brute));
    worst_fine = std::max(worst_fine, std::abs(g_fast - g_fine));
    EXPECT_NEAR(g_fast, g_fine, 1e-7) << x.transpose();
    EXPECT_NEAR(g_fast, g_brute, 1e-5) << x.transpose();
  }
  RecordProperty("worst_vs_default", std::to_string(worst_default));
  RecordProperty("worst_vs_fine", std::to_string(worst_fine));
  std::printf("fast vs default quadrature: %.3g, vs fine: %.3g\n", worst_default, worst_fine);
  // A flat wall against the independent radial reference, and far from every wall.
  const double L = 3.0;
  const auto plane =
      rectangle_elements(Vec3d(-L, -L, 0), Vec3d(2 * L, 0, 0), Vec3d(0, 2 * L, 0), dx);
  std::vector<std::size_t> pall(plane.size());
  for (std::size_t j = 0; j < pall.size(); ++j) pall[j] = j;
  const GeometricShepard<3> fplane(plane, h);
  for (double d : {0.1, 0.5, 1.0, 1.5})
    EXPECT_NEAR(fplane(plane, pall, Vec3d(0.1, 0.2, d)), reference_flat_3d(d), 1e-6) << d;
  EXPECT_NEAR(fplane(plane, pall, Vec3d(0.1, 0.2, 0.0)), 0.5, 1e-8);
  EXPECT_EQ(fplane(plane, pall, Vec3d(0.1, 0.2, 2.01)), 1.0);
}

TEST(GeometricShepardFast, MatchesBruteForceOnCurvedPatches) {
  // Triangulated patches of a sphere of radius 2 (fluid inside): no coplanar twins, every
  // edge integrated.
  std::vector<std::array<Vec3d, 3>> tris;
  const int nt = 24, np = 48;
  const double R = 2.0;
  auto pt = [&](int i, int k) {
    const double th = pi * i / nt, ph = 2 * pi * k / np;
    return Vec3d(R * std::sin(th) * std::cos(ph), R * std::sin(th) * std::sin(ph),
                 R * std::cos(th));
  };
  for (int i = 0; i < nt; ++i)
    for (int k = 0; k < np; ++k) {
      const Vec3d a = pt(i, k), b = pt(i + 1, k), c = pt(i + 1, k + 1), d = pt(i, k + 1);
      // Counter-clockwise seen from the centre (the fluid side).
      if (i > 0) tris.push_back({a, d, b});
      if (i + 1 < nt) tris.push_back({b, d, c});
    }
  const auto el = triangle_elements(tris);
  const GeometricShepard<3> fast(el, h);
  ShepardQuadrature fine;
  fine.gauss_points = 8;
  fine.max_piece_over_h = 0.125;
  std::vector<std::size_t> all(el.size());
  for (std::size_t j = 0; j < all.size(); ++j) all[j] = j;
  for (const Vec3d& x : {Vec3d(0, 0, 0), Vec3d(0.3, 0.2, 1.5), Vec3d(1.2, -0.9, 0.4),
                         Vec3d(0, 0, 1.9), Vec3d(-1.0, 1.0, -1.0)})
    EXPECT_NEAR(fast(el, all, x), shepard_geometric<3>(el, x, h, fine), 1e-7) << x.transpose();
}

// The flat-face fast path of GeometricShepard (a face covering the support disc gives the
// half-space value in closed form) against the independent radial reference, and across
// the switch to the rim quadrature as x approaches the face's rim: a 6 x 6 face, points at
// heights 0.02 h .. 1.99 h, sliding from the centre (disc covered) over the rim to outside.
TEST(GeometricShepardFast, CoveredFaceClosedFormAndSwitch) {
  const double L = 3.0;
  const auto plane =
      rectangle_elements(Vec3d(-L, -L, 0), Vec3d(2 * L, 0, 0), Vec3d(0, 2 * L, 0), dx);
  std::vector<std::size_t> all(plane.size());
  for (std::size_t j = 0; j < all.size(); ++j) all[j] = j;
  const GeometricShepard<3> fast(plane, h);
  for (double d : {0.02, 0.3, 0.77, 1.4, 1.99})
    EXPECT_NEAR(fast(plane, all, Vec3d(-0.3, 0.45, d)), reference_flat_3d(d), 1e-6) << d;
  ShepardQuadrature fine;
  fine.gauss_points = 8;
  fine.max_piece_over_h = 0.125;
  for (double d : {0.02, 0.6, 1.5})
    for (double xr = 0.0; xr <= 3.6; xr += 0.3) {
      const Vec3d x(xr, 0.37 * xr, d);
      EXPECT_NEAR(fast(plane, all, x), shepard_geometric<3>(plane, x, h, fine), 1e-7)
          << x.transpose();
    }
}
