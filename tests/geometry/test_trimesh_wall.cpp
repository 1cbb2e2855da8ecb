// Triangle-mesh walls against the exact shapes they tessellate: signed distance (value within
// the facets' depth, sign against a brute-force winding number), and the estimated principal
// curvatures against 1/R on a sphere and a cylinder at 2-degree facets, 0 on a cube.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <random>

#include "../support/test_meshes.hpp"
#include "curvsph/boundary/ghost/ghost_map.hpp"
#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/trimesh_wall.hpp"

namespace {

using curvsph::TriMeshWall;
using curvsph::Vec3d;
using curvsph::WallPoint;
using curvsph::testing::TestMesh;

std::shared_ptr<TriMeshWall> wall_of(const TestMesh& m, TriMeshWall::Side side) {
  return std::make_shared<TriMeshWall>(m.v, m.t, side);
}

// Winding number of the closed mesh about x: the sum of the triangles' signed solid angles
// (Van Oosterom & Strackee 1983) over 4 pi; 1 inside, 0 outside.
double winding_number(const TestMesh& m, const Vec3d& x) {
  double w = 0;
  for (const auto& T : m.t) {
    const Vec3d a = m.v[T[0]] - x, b = m.v[T[1]] - x, c = m.v[T[2]] - x;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    w += 2 * std::atan2(a.dot(b.cross(c)),
                        la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return w / (4 * std::numbers::pi);
}

// Unsigned distance from x to triangle abc by brute force: the plane when the projection
// falls inside, else the nearest of the three segments.
double triangle_distance(const Vec3d& x, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d n = (b - a).cross(c - a).normalized();
  const Vec3d p = x - n.dot(x - a) * n;
  const auto inside = [&](const Vec3d& u, const Vec3d& v) {
    return (v - u).cross(p - u).dot(n) >= 0;
  };
  if (inside(a, b) && inside(b, c) && inside(c, a)) return std::abs(n.dot(x - a));
  const auto seg = [&](const Vec3d& u, const Vec3d& v) {
    const double s = std::clamp((x - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
    return (x - (u + s * (v - u))).norm();
  };
  return std::min({seg(a, b), seg(b, c), seg(c, a)});
}

double brute_distance(const TestMesh& m, const Vec3d& x) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& T : m.t) d = std::min(d, triangle_distance(x, m.v[T[0]], m.v[T[1]], m.v[T[2]]));
  return d;
}

// Points in the box [-r, r]^3 and, as many, near the surface's edges and vertices (where the
// pseudo-normals decide the sign): vertices and edge midpoints displaced at random.
std::vector<Vec3d> probe_points(const TestMesh& m, double r, double near, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<Vec3d> x;
  for (int i = 0; i < n; ++i) x.emplace_back(r * U(rng), r * U(rng), r * U(rng));
  std::uniform_int_distribution<int> pick(0, int(m.t.size()) - 1);
  for (int i = 0; i < n; ++i) {
    const auto& T = m.t[pick(rng)];
    const Vec3d base = i % 2 ? m.v[T[0]] : Vec3d(0.5 * (m.v[T[0]] + m.v[T[1]]));
    x.push_back(base + near * Vec3d(U(rng), U(rng), U(rng)));
  }
  return x;
}

// Signed distance to the box [-h, h]^3, > 0 outside.
double box_sdf(const Vec3d& x, double h) {
  const Vec3d q = x.cwiseAbs() - Vec3d::Constant(h);
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

void check_distance(const TestMesh& m, const std::vector<Vec3d>& pts) {
  const auto out = wall_of(m, TriMeshWall::Side::outside);
  const auto in = wall_of(m, TriMeshWall::Side::inside);
  int wrong = 0;
  for (const Vec3d& x : pts) {
    const double d = brute_distance(m, x), w = winding_number(m, x);
    ASSERT_TRUE(std::abs(w) < 1e-6 || std::abs(w - 1) < 1e-6) << w;
    const double sd = w > 0.5 ? -d : d;  // > 0 outside
    const WallPoint<3> po = out->closest(x), pi = in->closest(x);
    EXPECT_NEAR(po.distance, sd, 1e-12) << x.transpose();
    EXPECT_NEAR(pi.distance, -sd, 1e-12) << x.transpose();
    EXPECT_NEAR((x - po.foot).norm(), d, 1e-12);
    if (d > 1e-9) wrong += po.normal.dot(x - po.foot) * sd < 0;  // normal into the fluid
  }
  EXPECT_EQ(wrong, 0);
}

TEST(TriMeshWall, CubeSignedDistanceIsTheBoxs) {
  for (int n : {1, 3}) {
    const TestMesh m = curvsph::testing::cube_mesh(0.5, n);
    ASSERT_NEAR(m.volume(), 1.0, 1e-12);
    const auto pts = probe_points(m, 1.0, 0.2, 300, 7 + n);
    check_distance(m, pts);
    const auto wall = wall_of(m, TriMeshWall::Side::outside);
    for (const Vec3d& x : pts) EXPECT_NEAR(wall->closest(x).distance, box_sdf(x, 0.5), 1e-12);
  }
}

TEST(TriMeshWall, SphereSignedDistanceWithinFacetDepth) {
  const double R = 0.8;
  const TestMesh m = curvsph::testing::uv_sphere(R, 10.0);
  ASSERT_GT(m.volume(), 0);
  // Every facet lies between the sphere and the sphere of the nearest facet plane: the
  // distance to the mesh differs from |x| - R by at most R - (that plane's distance).
  double r_in = R;
  for (const auto& T : m.t) {
    const Vec3d n = (m.v[T[1]] - m.v[T[0]]).cross(m.v[T[2]] - m.v[T[0]]).normalized();
    r_in = std::min(r_in, n.dot(m.v[T[0]]));
  }
  const double depth = R - r_in;
  const auto pts = probe_points(m, 1.5 * R, 0.1 * R, 300, 3);
  check_distance(m, pts);
  const auto wall = wall_of(m, TriMeshWall::Side::inside);
  for (const Vec3d& x : pts) {
    const double exact = R - x.norm(), d = wall->closest(x).distance;
    EXPECT_LE(std::abs(d - exact), depth + 1e-12);
    if (std::abs(exact) > depth) {
      EXPECT_GT(d * exact, 0) << x.transpose();
    }
  }
}

// Query points near faces, edges and vertices: a random point of a random triangle, a random
// point of one of its edges, or one of its vertices, displaced along the exact normal `nrm`
// by +-0.05 R.
template <class Normal>
std::vector<Vec3d> surface_probes(const TestMesh& m, double R, int n, unsigned seed, Normal&& nrm) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::uniform_int_distribution<int> pick(0, int(m.t.size()) - 1);
  std::vector<Vec3d> x;
  for (int i = 0; i < n; ++i) {
    const auto& T = m.t[pick(rng)];
    double b1 = U(rng), b2 = U(rng);
    if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
    if (i % 3 == 1) b2 = 0;       // on edge 0-1
    if (i % 3 == 2) b1 = b2 = 0;  // on vertex 0
    const Vec3d p = (1 - b1 - b2) * m.v[T[0]] + b1 * m.v[T[1]] + b2 * m.v[T[2]];
    x.push_back(p + (i % 2 ? 0.05 : -0.05) * R * nrm(p));
  }
  return x;
}

TEST(TriMeshWall, SphereCurvatureWithin3Percent) {
  const double R = 0.3;
  // A latitude-longitude sphere (fans and slivers at the poles) and an icosphere, both with
  // facets of about 2 degrees.
  for (const TestMesh& m :
       {curvsph::testing::uv_sphere(R, 2.0), curvsph::testing::icosphere(R, 32)}) {
    const auto pts = surface_probes(m, R, 3000, 11, [](const Vec3d& p) { return p.normalized(); });
    for (auto side : {TriMeshWall::Side::outside, TriMeshWall::Side::inside}) {
      const auto wall = wall_of(m, side);
      const double k = side == TriMeshWall::Side::inside ? 1 / R : -1 / R;  // concave from inside
      double err = 0;
      for (const Vec3d& x : pts) {
        const WallPoint<3> p = wall->closest(x);
        err = std::max({err, std::abs(p.k1 - k) * R, std::abs(p.k2 - k) * R});
        EXPECT_GE(p.k1, p.k2);
        EXPECT_NEAR(p.dir1.dot(p.normal), 0, 1e-12);
        EXPECT_NEAR(p.dir1.norm(), 1, 1e-12);
        EXPECT_NEAR(p.dir2.dot(p.dir1), 0, 1e-12);
      }
      std::cout << "sphere of " << m.t.size() << " triangles, fluid "
                << (k > 0 ? "inside" : "outside") << ": max relative kappa error " << err << '\n';
      EXPECT_LT(err, 0.03);
      EXPECT_NEAR(wall->min_radius_of_curvature(), R, 0.03 * R);
    }
  }
}

// An irregular mesh (grid points jittered by up to a quarter step) of a surface whose normal
// curvature varies: the estimate must not depend on the mesh being symmetric.
TEST(TriMeshWall, JitteredTorusCurvature) {
  const double R = 1.0, a = 0.3;
  const TestMesh m = curvsph::testing::torus_mesh(R, a, 2.0, 0.25, 4);
  ASSERT_GT(m.volume(), 0);
  const auto nrm = [&](const Vec3d& p) {
    const double ph = std::atan2(p.y(), p.x());
    return Vec3d(p - R * Vec3d(std::cos(ph), std::sin(ph), 0)).normalized();
  };
  const auto pts = surface_probes(m, a, 2000, 9, nrm);
  const auto wall = wall_of(m, TriMeshWall::Side::inside);
  double err = 0;
  for (const Vec3d& x : pts) {
    const WallPoint<3> p = wall->closest(x);
    // Fluid inside: 1/a across the tube, cos(theta) / (R + a cos(theta)) along it.
    const double th = std::atan2(p.foot.z(), std::hypot(p.foot.x(), p.foot.y()) - R);
    const double k_ring = std::cos(th) / (R + a * std::cos(th));
    err = std::max({err, std::abs(p.k1 - 1 / a) * a, std::abs(p.k2 - k_ring) * a});
  }
  std::cout << "jittered torus 2 deg: max |kappa error| * a " << err << '\n';
  EXPECT_LT(err, 0.02);
}

TEST(TriMeshWall, CylinderCurvatureWithin3Percent) {
  const double R = 0.25, L = 0.5;
  const TestMesh m = curvsph::testing::capped_cylinder(R, L, 2.0);
  ASSERT_GT(m.volume(), 0);
  // Probes on the side only (the caps are flat: checked below), rim rows included.
  TestMesh side_only = m;
  std::erase_if(side_only.t, [&](const auto& T) {
    return std::abs(m.v[T[0]].z() - m.v[T[1]].z()) + std::abs(m.v[T[1]].z() - m.v[T[2]].z()) == 0 &&
           std::abs(m.v[T[0]].z()) == L / 2;
  });
  auto pts = surface_probes(side_only, R, 3000, 5,
                            [](const Vec3d& p) { return Vec3d(p.x(), p.y(), 0).normalized(); });
  // Probes displaced inward by 0.05 R within 0.05 R of a cap are nearer the cap: leave them.
  std::erase_if(pts, [&](const Vec3d& x) { return std::abs(x.z()) > L / 2 - 0.06 * R; });
  for (auto side : {TriMeshWall::Side::outside, TriMeshWall::Side::inside}) {
    const auto wall = wall_of(m, side);
    const bool inside = side == TriMeshWall::Side::inside;
    double err = 0, dir_err = 0;
    for (const Vec3d& x : pts) {
      const WallPoint<3> p = wall->closest(x);
      // Fluid inside: k1 = 1/R (around), k2 = 0 (along the axis); outside: k1 = 0, k2 = -1/R.
      const double curved = inside ? p.k1 : p.k2, flat = inside ? p.k2 : p.k1;
      err = std::max({err, std::abs(curved - (inside ? 1 / R : -1 / R)) * R, std::abs(flat) * R});
      const Vec3d& around = inside ? p.dir1 : p.dir2;
      dir_err = std::max(dir_err, std::abs(around.z()));
    }
    std::cout << "cylinder 2 deg, fluid " << (inside ? "inside" : "outside")
              << ": max relative kappa error " << err << ", max |dir . axis| of the curved "
              << "direction " << dir_err << '\n';
    EXPECT_LT(err, 0.03);
    EXPECT_LT(dir_err, 0.05);
    // The caps: flat up to the rim (the rim is a crease the estimate does not cross).
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int i = 0; i < 200; ++i) {
      const Vec3d x(0.7 * R * U(rng), 0.7 * R * U(rng),
                    (i % 2 ? 1 : -1) * (L / 2 + 0.02 * R * U(rng)));
      const WallPoint<3> p = wall->closest(x);
      EXPECT_NEAR(p.k1 * R, 0, 1e-9);
      EXPECT_NEAR(p.k2 * R, 0, 1e-9);
    }
  }
}

TEST(TriMeshWall, CubeFacesAreFlatUpToTheirEdges) {
  const TestMesh m = curvsph::testing::cube_mesh(0.5, 8);
  const auto wall = wall_of(m, TriMeshWall::Side::inside);
  for (const Vec3d& x : probe_points(m, 0.7, 0.1, 500, 1)) {
    const WallPoint<3> p = wall->closest(x);
    EXPECT_NEAR(p.k1, 0, 1e-9) << x.transpose();
    EXPECT_NEAR(p.k2, 0, 1e-9) << x.transpose();
  }
  EXPECT_EQ(wall->min_radius_of_curvature(), std::numeric_limits<double>::infinity());
}

// The set-up check of the curvature-aware ghost maps decides on a tessellated sphere as on the
// exact one: accepts a support small against R, refuses one too large on the convex side.
TEST(TriMeshWall, GhostWallCheckAgreesWithTheExactSphere) {
  const double R = 1.0;
  const TestMesh m = curvsph::testing::uv_sphere(R, 2.0);
  for (auto side : {curvsph::FluidSide::inside, curvsph::FluidSide::outside}) {
    curvsph::WallSet<3> mesh, exact;
    mesh.add(wall_of(m, side == curvsph::FluidSide::inside ? TriMeshWall::Side::inside
                                                           : TriMeshWall::Side::outside));
    exact.add(std::make_shared<curvsph::SphereWall>(Vec3d::Zero(), R, side));
    std::vector<curvsph::Vec<3>> fluid;
    for (int i = 0; i < 50; ++i) {
      const double a = 0.37 * i, b = 0.11 * i;
      const double r = side == curvsph::FluidSide::inside ? 0.9 * R : 1.1 * R;
      fluid.push_back((r * Vec3d(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b)))
                          .cast<curvsph::Real>());
    }
    const double k = side == curvsph::FluidSide::inside ? 1 / R : -1 / R;
    for (auto map :
         {curvsph::GhostMapKind::mirror_beta, curvsph::GhostMapKind::density_preserving}) {
      // Supports well inside and well beyond the exact sphere's limit (where it has one).
      const double limit = curvsph::ghost_max_depth(map, k, k);
      std::vector<double> supports{0.1 * R};
      if (limit < 10 * R) supports.insert(supports.end(), {0.8 * limit, 1.25 * limit});
      for (double support : supports) {
        bool refused_exact = false, refused_mesh = false;
        try {
          curvsph::check_ghost_walls<3>(map, exact, support, fluid, "case.yaml");
        } catch (const curvsph::InputError&) {
          refused_exact = true;
        }
        try {
          curvsph::check_ghost_walls<3>(map, mesh, support, fluid, "case.yaml");
        } catch (const curvsph::InputError&) {
          refused_mesh = true;
        }
        EXPECT_EQ(refused_mesh, support > limit)
            << curvsph::to_string(map) << " support " << support << " fluid "
            << curvsph::to_string(side);
        EXPECT_EQ(refused_exact, support > limit);
      }
    }
  }
}

}  // namespace
