// The surge front on a floor (analysis/floor_front.hpp) on hand-made particle sets: against a
// brute-force evaluation (every particle and an explicit mirror copy of it, the Wendland C2
// formula written out here, a plain walk over samples), and against the continuum: the
// interpolated indicator of water filling x < x_edge is 1/2 at x_edge by the kernel's symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "curvsph/analysis/floor_front.hpp"

namespace curvsph {
namespace {

constexpr double kDx = 0.01, kH = 2 * kDx, kFloor = -0.3;

struct Set {
  std::vector<Vec<2>> x;
  std::vector<Real> V;
  void add(double px, double py) {
    x.emplace_back(static_cast<Real>(px), static_cast<Real>(py));
    V.push_back(static_cast<Real>(kDx * kDx));
  }
  // cols x rows particles on the floor, the first column's centre at x0.
  void block(double x0, int cols, int rows) {
    for (int i = 0; i < cols; ++i)
      for (int j = 0; j < rows; ++j) add(x0 + i * kDx, kFloor + (j + 0.5) * kDx);
  }
};

// Brute force: the indicator interpolant summed over all particles and their explicit images in
// the floor, sampled every dx/4 from x_start; the last crossing below 1/2 after a wet sample.
double brute_wet_x(const Set& s, double x_start) {
  std::vector<Vec<2>> all = s.x;
  std::vector<Real> V = s.V;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    all.emplace_back(s.x[i].x(), static_cast<Real>(2 * kFloor - s.x[i].y()));
    V.push_back(s.V[i]);
  }
  const auto W = [](double r) {
    const double q = r / kH;
    return q >= 2 ? 0.0
                  : 7 / (4 * std::numbers::pi * kH * kH) * std::pow(1 - q / 2, 4) * (2 * q + 1);
  };
  const auto phi = [&](double xs) {
    double sum = 0;
    for (std::size_t i = 0; i < all.size(); ++i)
      sum += V[i] * W(std::hypot(all[i].x() - xs, all[i].y() - (kFloor + kDx / 2)));
    return sum;
  };
  double prev = 0, front = std::numeric_limits<double>::quiet_NaN();
  for (int n = 0; n < 2000; ++n) {  // to x_start + 5 m, far past every particle here
    const double xs = x_start + n * kDx / 4, p = phi(xs);
    if (prev >= 0.5 && p < 0.5) front = xs - kDx / 4 + (0.5 - prev) / (p - prev) * kDx / 4;
    prev = p;
  }
  return front;
}

TEST(FloorFront, AgainstBruteForceWithFilmSprayAndDroplet) {
  Set s;
  s.block(0.005, 40, 20);  // the column's foot, 40 dx long, 20 rows
  s.block(0.405, 15, 2);   // a sheet two particles thick
  s.block(0.555, 10, 1);   // a single row: phi = 0.61 at h = 2 dx, still wet
  for (int k = 0; k < 5; ++k) s.add(0.68 + 0.025 * k, kFloor + kDx / 2);  // spray 2.5 dx apart
  s.add(0.80, kFloor + 0.004);  // one particle sliding ahead on the floor: the largest x
  s.add(1.20, kFloor + 0.2);    // a droplet in the air: neither front
  const FloorFront f = floor_front(s.x, s.V, kFloor, 0.1, kDx, kH);
  EXPECT_NEAR(f.wet_x, brute_wet_x(s, 0.1), 1e-9);
  EXPECT_NEAR(f.largest_x, 0.80, 1e-6);
  // The wet front ends with the single row (last centre 0.645, edge 0.65), before the spray.
  EXPECT_GT(f.wet_x, 0.645 - kDx);
  EXPECT_LT(f.wet_x, 0.65 + kDx);
}

TEST(FloorFront, HalfSpaceEdgeIsTheFront) {
  // Water filling the floor up to x_edge = 0.6 (centres dx/2 inside), deep: phi(x_edge) = 1/2 in
  // the continuum; the lattice sum is within a fraction of a per cent of it.
  Set s;
  s.block(0.005, 60, 30);
  const FloorFront f = floor_front(s.x, s.V, kFloor, 0.1, kDx, kH);
  EXPECT_NEAR(f.wet_x, 0.6, 0.02 * kDx);
  EXPECT_NEAR(f.largest_x, 0.595, 1e-6);
  // A start inside a dry stretch (the column has left the wall), and a dry patch 10 dx long
  // behind the front: the front is the far edge, 1.0.
  Set t;
  t.block(0.305, 30, 30);
  t.block(0.705, 30, 3);
  const FloorFront ft = floor_front(t.x, t.V, kFloor, 0.0, kDx, kH);
  EXPECT_NEAR(ft.wet_x, 1.0, 0.02 * kDx);
  EXPECT_NEAR(ft.wet_x, brute_wet_x(t, 0.0), 1e-9);
  // Nothing wet: NaN.
  Set u;
  u.add(0.3, kFloor + kDx / 2);
  EXPECT_TRUE(std::isnan(floor_front(u.x, u.V, kFloor, 0.0, kDx, kH).wet_x));
}

}  // namespace
}  // namespace curvsph
