// Boundary elements of triangle-mesh (STL) walls: areas equal to the mesh's, closed meshes
// closed, normals into the fluid, and the geometric Shepard factor on them: a tessellated
// sphere against the analytic ball, and a box whose faces are split unevenly (T-junctions
// along straight edges) against adaptive quadrature of W over the box at its faces, edges and
// corners, fluid inside and outside.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <numeric>
#include <random>

#include "../support/shepard_reference.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/geometry/trimesh_wall.hpp"

using namespace curvsph;

namespace {

constexpr double pi = std::numbers::pi;
using Tris = std::vector<std::array<int, 3>>;

// Icosahedron subdivided `levels` times, vertices projected on the sphere (counter-clockwise
// seen from outside, the STL convention).
void icosphere(const Vec3d& c, double R, int levels, std::vector<Vec3d>& v, Tris& t) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  v = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
       {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  t = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
       {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
       {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& p : v) p.normalize();
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[static_cast<std::size_t>(a)] + v[static_cast<std::size_t>(b)]).normalized());
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    Tris next;
    for (const auto& [a, b, cc] : t) {
      const int ab = midpoint(a, b), bc = midpoint(b, cc), ca = midpoint(cc, a);
      next.insert(next.end(), {{a, ab, ca}, {b, bc, ab}, {cc, ca, bc}, {ab, bc, ca}});
    }
    t = std::move(next);
  }
  for (auto& p : v) p = c + R * p;
}

double mesh_area(const std::vector<Vec3d>& v, const Tris& t) {
  double a = 0;
  for (const auto& [i, j, k] : t)
    a += 0.5 * (v[static_cast<std::size_t>(j)] - v[static_cast<std::size_t>(i)])
                   .cross(v[static_cast<std::size_t>(k)] - v[static_cast<std::size_t>(i)])
                   .norm();
  return a;
}

double fast_gamma(const BoundaryElements<3>& el, const GeometricShepard<3>& g, const Vec3d& x) {
  std::vector<std::size_t> all(el.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  return g(el, all, x);
}

}  // namespace

TEST(TriMeshElements, TessellatedSphereAgainstTheBall) {
  const double R = 1.0, h = 0.1, dx = 0.05;
  const Vec3d c(0.2, -0.1, 0.3);
  std::vector<Vec3d> v;
  Tris t;
  icosphere(c, R, 5, v, t);  // 20480 triangles, edges about 0.03
  double worst = 0;
  for (auto side : {TriMeshWall::Side::inside, TriMeshWall::Side::outside}) {
    const bool inside = side == TriMeshWall::Side::inside;
    const TriMeshWall wall(v, t, side);
    const auto el = elements_from_wall<3>(wall, dx, {});
    ASSERT_EQ(el.size(), t.size());  // edges below dx: one element per triangle
    EXPECT_NEAR(std::accumulate(el.area.begin(), el.area.end(), 0.0) / mesh_area(v, t), 1.0, 1e-12);
    Vec3d closure = Vec3d::Zero();
    for (std::size_t j = 0; j < el.size(); ++j) {
      closure += el.normal[j] * el.area[j];
      EXPECT_EQ(el.normal[j].dot(el.centre[j] - c) < 0, inside);
    }
    EXPECT_LT(closure.norm(), 1e-12);
    const GeometricShepard<3> fast(el, h);
    std::mt19937 rng(7);
    std::normal_distribution<double> gauss(0, 1);
    for (int k = 0; k < 4; ++k) {
      const Vec3d dir = Vec3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
      for (double d : {2.0, 1.5, 1.0, 0.5, 0.2, 0.1}) {
        const double r = inside ? R - d * h : R + d * h;
        const double ref = test::reference_gamma_ball(r, R, h, inside);
        const Vec3d x = c + r * dir;
        const double e = std::max(std::abs(shepard_geometric<3>(el, x, h) - ref),
                                  std::abs(fast_gamma(el, fast, x) - ref));
        worst = std::max(worst, e);
        EXPECT_LT(e, 0.005) << "inside " << inside << " d/h " << d;
      }
    }
    // On the mesh's vertices (on the sphere): the ball's on-wall value.
    const double on = test::reference_gamma_ball(R, R, h, inside);
    for (std::size_t i = 0; i < v.size(); i += v.size() / 9) {
      const double e = std::max(std::abs(shepard_geometric<3>(el, v[i], h) - on),
                                std::abs(fast_gamma(el, fast, v[i]) - on));
      worst = std::max(worst, e);
      EXPECT_LT(e, 0.005) << "vertex " << i;
    }
  }
  std::printf("tessellated sphere (20480 triangles) vs the ball: max |gamma - ref| = %.2e\n",
              worst);
}

TEST(TriMeshElements, SplitBoxFacesEdgesAndCorners) {
  // Box [0,1] x [0,2] x [0,0.5]; the bottom as a fan about (0.3, 0.7, 0) so that its
  // triangles are split into different counts (T-junctions inside the face), the other faces
  // as two triangles each.
  const double h = 0.1, dx = 0.05;
  const Vec3d lo(0, 0, 0), hi(1, 2, 0.5);
  std::vector<Vec3d> v;
  for (int k = 0; k < 8; ++k)
    v.push_back(Vec3d(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z()));
  v.push_back(Vec3d(0.3, 0.7, 0));  // 8: fan centre of the bottom
  // Outward counter-clockwise quads (corner index bits: x = 1, y = 2, z = 4).
  const std::vector<std::array<int, 4>> quads = {
      {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  Tris t;
  for (const auto& q : quads) {
    t.push_back({q[0], q[1], q[2]});
    t.push_back({q[0], q[2], q[3]});
  }
  for (const auto& [a, b] : {std::pair{0, 2}, {2, 3}, {3, 1}, {1, 0}}) t.push_back({8, a, b});
  double worst = 0;
  for (auto side : {TriMeshWall::Side::inside, TriMeshWall::Side::outside}) {
    const bool inside = side == TriMeshWall::Side::inside;
    const TriMeshWall wall(v, t, side);
    const auto el = elements_from_wall<3>(wall, dx, {});
    EXPECT_NEAR(std::accumulate(el.area.begin(), el.area.end(), 0.0), 2 * (2 + 0.5 + 1), 1e-11);
    Vec3d closure = Vec3d::Zero();
    double longest = 0;
    for (std::size_t j = 0; j < el.size(); ++j) {
      closure += el.normal[j] * el.area[j];
      EXPECT_EQ(el.normal[j].dot(Vec3d(0.5, 1, 0.25) - el.centre[j]) > 0, inside);
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest, (el.vertices[j][static_cast<std::size_t>(k)] -
                                     el.vertices[j][static_cast<std::size_t>((k + 1) % 3)])
                                        .norm());
    }
    EXPECT_LT(closure.norm(), 1e-12);
    EXPECT_LT(longest, 2.5 * dx);
    const GeometricShepard<3> fast(el, h);
    const test::Columns fluid = [&](double X, double Y) {
      const bool over = X > lo.x() && X < hi.x() && Y > lo.y() && Y < hi.y();
      std::vector<std::pair<double, double>> out;
      if (inside && over) out.push_back({lo.z(), hi.z()});
      if (!inside && over) out = {{-1e300, lo.z()}, {hi.z(), 1e300}};
      if (!inside && !over) out.push_back({-1e300, 1e300});
      return out;
    };
    const double s = inside ? 1.0 : -1.0;
    struct Probe {
      const char* what;
      Vec3d base, dir;
    };
    const std::vector<Probe> probes = {
        {"bottom at the fan centre", Vec3d(0.3, 0.7, 0), s * Vec3d(0, 0, 1)},
        {"bottom", Vec3d(0.62, 1.31, 0), s * Vec3d(0, 0, 1)},
        {"edge x = 0, z = 0", Vec3d(0, 1.1, 0), s * Vec3d(1, 0, 1).normalized()},
        {"corner (0, 0, 0)", lo, s * Vec3d(1, 1, 1).normalized()},
        {"corner (1, 2, 0.5)", hi, -s * Vec3d(1, 1, 1).normalized()}};
    for (const Probe& pr : probes) {
      double worst_here = 0;
      for (double d : {1.5, 1.0, 0.5, 0.2, 0.05, 0.0}) {
        const Vec3d x = pr.base + d * h * pr.dir;
        const double ref = test::reference_gamma_3d(x, h, fluid);
        const double e = std::max(std::abs(shepard_geometric<3>(el, x, h) - ref),
                                  std::abs(fast_gamma(el, fast, x) - ref));
        worst_here = std::max(worst_here, e);
        EXPECT_LT(e, 0.005) << pr.what << " inside " << inside << " d/h " << d << " ref " << ref;
      }
      std::printf("split STL box (%s), %s: max |gamma - ref| = %.2e\n",
                  inside ? "inside" : "outside", pr.what, worst_here);
      worst = std::max(worst, worst_here);
    }
  }
  std::printf("split STL box: max |gamma - ref| = %.2e\n", worst);
}
