#pragma once
// Shared NURBS test geometries: the exact rational quadratic circle and random rational
// curves/surfaces with fixed seeds.
#include <cmath>
#include <random>
#include <vector>

#include "curvsph/nurbs/curve.hpp"
#include "curvsph/nurbs/surface.hpp"

namespace curvsph::test {

// Full circle of radius R about c, counter-clockwise, 9 control points, w = sqrt(2)/2 at
// the corners (P&T Ex. 7.2); knots 0,0,0,1,1,2,2,3,3,4,4,4.
inline nurbs::NurbsCurve<2> nurbs_circle(double R, Vec2d c = Vec2d::Zero()) {
  const double h = std::sqrt(0.5);
  std::vector<Vec2d> P = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                          {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  for (auto& p : P) p = c + R * p;
  return nurbs::NurbsCurve<2>(2, P, {1, h, 1, h, 1, h, 1, h, 1},
                              {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4});
}

// Random non-uniform knots (clamped), with some repeated interior knots.
inline std::vector<double> random_knots(std::mt19937& rng, int p, int n) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> k(p + 1, 0.0);
  const int interior = n - p - 1;
  std::vector<double> in;
  for (int i = 0; i < interior; ++i) in.push_back(0.05 + 0.9 * U(rng));
  std::sort(in.begin(), in.end());
  if (interior >= 3 && p >= 2) in[2] = in[1];  // a double knot
  for (double v : in) k.push_back(v);
  for (int i = 0; i <= p; ++i) k.push_back(1.0);
  return k;
}

template <int D>
nurbs::NurbsCurve<D> random_curve(unsigned seed, int p, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> X(-1.0, 1.0), W(0.3, 3.0);
  std::vector<VecD<D>> P(n);
  std::vector<double> w(n);
  for (int i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) P[i][d] = X(rng);
    P[i][0] += 0.6 * i;  // a wiggly curve going roughly along x
    w[i] = W(rng);
  }
  return nurbs::NurbsCurve<D>(p, P, w, random_knots(rng, p, n));
}

inline nurbs::NurbsSurface random_surface(unsigned seed, int p, int q, int nu, int nv) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> X(-0.3, 0.3), W(0.4, 2.5);
  std::vector<std::vector<Vec3d>> P(nu, std::vector<Vec3d>(nv));
  std::vector<std::vector<double>> w(nu, std::vector<double>(nv));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      P[i][j] = Vec3d(i + X(rng), j + X(rng), 1.5 * X(rng) * (1 + (i + j) % 3));
      w[i][j] = W(rng);
    }
  return nurbs::NurbsSurface(p, q, P, w, random_knots(rng, p, nu), random_knots(rng, q, nv));
}

}  // namespace curvsph::test
