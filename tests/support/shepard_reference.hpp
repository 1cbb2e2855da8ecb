#pragma once
// Independent references for the Shepard factor gamma(x) = int over the fluid part of the
// support ball of x of W (Wendland C2), by adaptive quadrature of W over the fluid region
// itself (no boundary elements), for tests/boundary.
//  - 2-D: polar coordinates about x; the fluid part of each ray from an inside(y) predicate
//    (sampling + bisection), the radial integral by 8-point Gauss-Legendre per interval
//    (exact: W r is a polynomial of degree 6), the angle by adaptive Simpson.
//  - 3-D: columns along z. The fluid is given as the z-intervals above each point (X, Y) of
//    the plane (a height field, a box, a ball: any region whose vertical lines meet it in
//    intervals known in closed form or by evaluation). gamma = int over the support disc of x
//    in polar coordinates (rho, phi) about (x, y) of int_column W dz; the inner integral by
//    Gauss-Legendre on pieces split at z = x_z (the kink of W(|z - x_z|) on the axis), rho and
//    phi by adaptive Simpson (the integrand has kinks where the wall leaves the ball), rho cut
//    where the column's interval count changes along the ray (a jump).
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <utility>
#include <vector>

#include "curvsph/core/quadrature.hpp"
#include "curvsph/core/types.hpp"
#include "curvsph/kernels/wendland.hpp"

namespace curvsph::test {

inline double adaptive_simpson(const std::function<double(double)>& f, double a, double b,
                               double fa, double fm, double fb, double whole, double tol,
                               int depth) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * tol)
    return left + right + (left + right - whole) / 15;
  return adaptive_simpson(f, a, m, fa, flm, fm, left, tol / 2, depth - 1) +
         adaptive_simpson(f, m, b, fm, frm, fb, right, tol / 2, depth - 1);
}

// int_a^b f, adaptive Simpson on `sectors` equal sectors to absolute tolerance tol each.
inline double integrate(const std::function<double(double)>& f, double a, double b, int sectors,
                        double tol, int depth = 20) {
  double total = 0;
  for (int s = 0; s < sectors; ++s) {
    const double lo = a + (b - a) * s / sectors, hi = a + (b - a) * (s + 1) / sectors;
    const double fa = f(lo), fb = f(hi), fm = f(0.5 * (lo + hi));
    total +=
        adaptive_simpson(f, lo, hi, fa, fm, fb, (hi - lo) / 6 * (fa + 4 * fm + fb), tol, depth);
  }
  return total;
}

// ---- 2-D ----------------------------------------------------------------------------------

inline double ray_integral_2d(const Vec2d& x, double phi, double h,
                              const std::function<bool(const Vec2d&)>& inside) {
  const WendlandC2<2> W(h);
  auto radial_mass = [&](double r1, double r2) {
    return gauss_legendre_8([&](double r) { return W.value(r) * r; }, r1, r2);
  };
  const Vec2d e(std::cos(phi), std::sin(phi));
  const int n = 400;
  const double R = 2 * h;
  double sum = 0, start = 0;
  bool in = inside(x + 1e-13 * h * e);
  for (int k = 1; k <= n; ++k) {
    const double r = R * k / n;
    const bool now = inside(x + r * e);
    if (now != in) {
      double lo = R * (k - 1) / n, hi = r;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (inside(x + mid * e) == in ? lo : hi) = mid;
      }
      if (in) sum += radial_mass(start, lo);
      start = lo;
      in = now;
    }
  }
  if (in) sum += radial_mass(start, R);
  return sum;
}

inline double reference_gamma_2d(const Vec2d& x, double h,
                                 const std::function<bool(const Vec2d&)>& inside) {
  return integrate([&](double phi) { return ray_integral_2d(x, phi, h, inside); }, 0.0,
                   2 * std::numbers::pi, 16, 1e-9);
}

// ---- 3-D ----------------------------------------------------------------------------------

// The fluid's z-intervals on the vertical line through (X, Y), sorted, disjoint.
using Columns = std::function<std::vector<std::pair<double, double>>(double X, double Y)>;

inline double reference_gamma_3d(const Vec3d& x, double h, const Columns& fluid,
                                 double tol = 1e-8) {
  const WendlandC2<3> W(h);
  const double R = 2 * h;
  // int over the column at distance rho of W(sqrt(rho^2 + s^2)) dz, s = z - x_z.
  auto column = [&](double rho, double phi) {
    const double top = std::sqrt(std::max(R * R - rho * rho, 0.0));
    if (!(top > 0)) return 0.0;
    double sum = 0;
    for (const auto& [z0, z1] : fluid(x.x() + rho * std::cos(phi), x.y() + rho * std::sin(phi))) {
      const double a = std::max(z0 - x.z(), -top), b = std::min(z1 - x.z(), top);
      if (!(b > a)) continue;
      auto f = [&](double s) { return W.value(std::sqrt(rho * rho + s * s)); };
      auto piece = [&](double lo, double hi) {
        if (!(hi > lo)) return 0.0;
        return gauss_legendre_8(f, lo, hi,
                                std::max(1, static_cast<int>(std::ceil((hi - lo) / (0.25 * h)))));
      };
      sum += a < 0 && b > 0 ? piece(a, 0) + piece(0, b) : piece(a, b);
    }
    return sum * rho;
  };
  // Along each ray the column integral jumps where the number of fluid intervals changes (the
  // rim of a face seen from above): located by sampling and bisection, and the radial
  // integral cut there (adaptive Simpson alone can step over a jump).
  auto count = [&](double rho, double phi) {
    return fluid(x.x() + rho * std::cos(phi), x.y() + rho * std::sin(phi)).size();
  };
  auto ray = [&](double phi) {
    std::vector<double> cuts{0.0};
    const int n = 200;
    std::size_t prev = count(0.0, phi);
    for (int k = 1; k <= n; ++k) {
      const double rho = R * k / n;
      const std::size_t now = count(rho, phi);
      if (now != prev) {
        double lo = R * (k - 1) / n, hi = rho;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          (count(mid, phi) == prev ? lo : hi) = mid;
        }
        cuts.push_back(0.5 * (lo + hi));
        prev = now;
      }
    }
    cuts.push_back(R);
    double sum = 0;
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
      if (cuts[c + 1] > cuts[c])
        sum += integrate([&](double rho) { return column(rho, phi); }, cuts[c], cuts[c + 1], 2,
                         tol / 8, 14);
    return sum;
  };
  return integrate(ray, 0.0, 2 * std::numbers::pi, 16, tol, 14);
}

// gamma of the ball |y - c| <= R (inside) or its complement at distance r from c: the
// fraction of each kernel shell |y - x| = s inside the ball is (1 - c0) / 2 with c0 =
// (r^2 + s^2 - R^2) / (2 r s) clamped to [-1, 1]; Gauss-Legendre in s split at |R - r|.
inline double reference_gamma_ball(double r, double R, double h, bool inside) {
  const WendlandC2<3> W(h);
  auto f = [&](double s) {
    const double c0 = std::clamp((r * r + s * s - R * R) / (2 * r * s), -1.0, 1.0);
    const double frac = inside ? 0.5 * (1 - c0) : 0.5 * (1 + c0);
    return W.value(s) * 4 * std::numbers::pi * s * s * frac;
  };
  const double k = std::clamp(std::abs(R - r), 0.0, 2 * h);
  return (k > 0 ? gauss_legendre_8(f, 0.0, k, 16) : 0.0) + gauss_legendre_8(f, k, 2 * h, 16);
}

}  // namespace curvsph::test
