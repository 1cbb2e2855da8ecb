#pragma once
// Closed triangle meshes generated analytically for the mesh-wall tests: vertices computed
// from the exact shape, triangles oriented counter-clockwise seen from outside, plus the
// writers of the two STL formats.
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph::testing {

struct TestMesh {
  std::vector<Vec3d> v;
  std::vector<std::array<int, 3>> t;

  int vertex(const Vec3d& p) {  // shared vertices by exact coordinates
    const auto [it, fresh] = index.try_emplace({p.x(), p.y(), p.z()}, int(v.size()));
    if (fresh) v.push_back(p);
    return it->second;
  }
  // Adds triangle abc turned so that its normal points away from `inner` (a point the convex
  // shape contains on the normal's line: its centre, or its axis point for a cylinder side).
  void add(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& inner) {
    const Vec3d n = (b - a).cross(c - a);
    if (n.dot((a + b + c) / 3.0 - inner) >= 0)
      t.push_back({vertex(a), vertex(b), vertex(c)});
    else
      t.push_back({vertex(a), vertex(c), vertex(b)});
  }
  double volume() const {
    double s = 0;
    for (const auto& T : t) s += v[T[0]].dot(v[T[1]].cross(v[T[2]])) / 6.0;
    return s;
  }
  std::map<std::array<double, 3>, int> index;
};

inline double deg(double d) {
  return d * std::numbers::pi / 180.0;
}

// Cube [-h, h]^3, each face split into n x n squares of two triangles.
inline TestMesh cube_mesh(double h, int n) {
  TestMesh m;
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      const auto P = [&](int i, int j) {
        Vec3d p;
        p[a] = s * h;
        p[b] = -h + 2 * h * i / n;
        p[c] = -h + 2 * h * j / n;
        return p;
      };
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          m.add(P(i, j), P(i + 1, j), P(i + 1, j + 1), Vec3d::Zero());
          m.add(P(i, j), P(i + 1, j + 1), P(i, j + 1), Vec3d::Zero());
        }
    }
  return m;
}

// Latitude-longitude sphere of radius R, facets of `step` degrees in both angles (fans at the
// poles).
inline TestMesh uv_sphere(double R, double step) {
  TestMesh m;
  const int nlat = int(std::lround(180.0 / step)), nlon = int(std::lround(360.0 / step));
  const auto P = [&](int i, int j) {  // i = 0 .. nlat from the south pole
    if (i == 0) return Vec3d(0, 0, -R);
    if (i == nlat) return Vec3d(0, 0, R);
    const double th = deg(-90.0 + 180.0 * i / nlat), ph = 2 * std::numbers::pi * (j % nlon) / nlon;
    return Vec3d(R * std::cos(th) * std::cos(ph), R * std::cos(th) * std::sin(ph),
                 R * std::sin(th));
  };
  for (int i = 0; i < nlat; ++i)
    for (int j = 0; j < nlon; ++j) {
      if (i > 0) m.add(P(i, j), P(i, j + 1), P(i + 1, j + 1), Vec3d::Zero());
      if (i + 1 < nlat) m.add(P(i, j), P(i + 1, j + 1), P(i + 1, j), Vec3d::Zero());
    }
  return m;
}

// Icosphere of radius R: each face of the icosahedron split into n^2 triangles, vertices
// projected on the sphere (edges of about 63.4 / n degrees; valence 5 at the 12 corners).
inline TestMesh icosphere(double R, int n) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  const Vec3d c[12] = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                       {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  const int f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                        {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                        {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                        {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  TestMesh m;
  for (const auto& F : f) {
    // Points i a + j b + k c (i + j + k = n) of the flat face, then on the sphere. Rounding
    // the flat point to a lattice of 1e-12 first makes the shared edges' points bitwise equal.
    const auto P = [&](int i, int j) {
      Vec3d q = (double(n - i - j) * c[F[0]] + double(i) * c[F[1]] + double(j) * c[F[2]]) / n;
      for (int k = 0; k < 3; ++k) q[k] = std::round(q[k] * 1e12) / 1e12;
      return Vec3d(R * q.normalized());
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        m.add(P(i, j), P(i + 1, j), P(i, j + 1), Vec3d::Zero());
        if (i + j + 2 <= n) m.add(P(i + 1, j), P(i + 1, j + 1), P(i, j + 1), Vec3d::Zero());
      }
  }
  return m;
}

// Cylinder of radius R about the z axis, z in [-L/2, L/2], `step` degrees around, rows of about
// the same arc length along the axis, closed by fans to the caps' centres.
inline TestMesh capped_cylinder(double R, double L, double step) {
  TestMesh m;
  const int nphi = int(std::lround(360.0 / step));
  const int nz = std::max(1, int(std::lround(L / (R * deg(step)))));
  const auto P = [&](int k, int j) {
    const double ph = 2 * std::numbers::pi * (j % nphi) / nphi;
    return Vec3d(R * std::cos(ph), R * std::sin(ph), -L / 2 + L * k / nz);
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < nphi; ++j) {
      const Vec3d axis(0, 0, -L / 2 + L * (k + 0.5) / nz);
      m.add(P(k, j), P(k, j + 1), P(k + 1, j + 1), axis);
      m.add(P(k, j), P(k + 1, j + 1), P(k + 1, j), axis);
    }
  for (int j = 0; j < nphi; ++j) {
    m.add(Vec3d(0, 0, -L / 2), P(0, j), P(0, j + 1), Vec3d::Zero());
    m.add(Vec3d(0, 0, L / 2), P(nz, j), P(nz, j + 1), Vec3d::Zero());
  }
  return m;
}

// Torus about the z axis (major radius R, minor a): a grid of `step` degrees in the poloidal
// angle theta (0 on the outer equator) and the toroidal angle phi, each grid point moved in
// (theta, phi) by up to `jitter` of a step at random (so it stays on the torus), squares split
// into two triangles: an irregular mesh when jitter > 0.
inline TestMesh torus_mesh(double R, double a, double step, double jitter, unsigned seed) {
  const int n = int(std::lround(360.0 / step));
  const double h = 2 * std::numbers::pi / n;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<Vec3d> g(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double th = (i + jitter * U(rng)) * h, ph = (j + jitter * U(rng)) * h;
      g[i * n + j] = Vec3d((R + a * std::cos(th)) * std::cos(ph),
                           (R + a * std::cos(th)) * std::sin(ph), a * std::sin(th));
    }
  TestMesh m;
  const auto G = [&](int i, int j) { return g[(i % n) * n + j % n]; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      // Away from the tube's centre circle at this phi (convex across the tube).
      const double ph = (j + 0.5) * h;
      const Vec3d centre(R * std::cos(ph), R * std::sin(ph), 0);
      m.add(G(i, j), G(i + 1, j), G(i + 1, j + 1), centre);
      m.add(G(i, j), G(i + 1, j + 1), G(i, j + 1), centre);
    }
  return m;
}

inline void write_ascii_stl(const std::string& path, const TestMesh& m) {
  std::ofstream f(path);
  f.precision(17);
  f << "solid test\n";
  for (const auto& T : m.t) {
    f << "  facet normal 0 0 0\n    outer loop\n";
    for (int c = 0; c < 3; ++c)
      f << "      vertex " << m.v[T[c]].x() << ' ' << m.v[T[c]].y() << ' ' << m.v[T[c]].z() << '\n';
    f << "    endloop\n  endfacet\n";
  }
  f << "endsolid test\n";
}

// Binary STL; `count` overrides the declared triangle count (a corrupt file).
inline void write_binary_stl(const std::string& path, const TestMesh& m, long count = -1) {
  std::ofstream f(path, std::ios::binary);
  const char header[80] = "binary test mesh";
  f.write(header, 80);
  const std::uint32_t n = count < 0 ? std::uint32_t(m.t.size()) : std::uint32_t(count);
  f.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& T : m.t) {
    float r[12] = {0, 0, 0};
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) r[3 + 3 * c + k] = float(m.v[T[c]][k]);
    f.write(reinterpret_cast<const char*>(r), sizeof r);
    const std::uint16_t attr = 0;
    f.write(reinterpret_cast<const char*>(&attr), 2);
  }
}

}  // namespace curvsph::testing
