#include "curvsph/nurbs/sampling.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace curvsph::nurbs {
namespace {

// 7-point Gauss-Legendre nodes/weights on [-1, 1] (Abramowitz & Stegun 25.4.30).
constexpr std::array<double, 7> kX = {0.0,
                                      0.4058451513773971669066064,
                                      -0.4058451513773971669066064,
                                      0.7415311855993944398638648,
                                      -0.7415311855993944398638648,
                                      0.9491079123427585245261897,
                                      -0.9491079123427585245261897};
constexpr std::array<double, 7> kW = {0.4179591836734693877551020, 0.3818300505051189449503698,
                                      0.3818300505051189449503698, 0.2797053914892766679014678,
                                      0.2797053914892766679014678, 0.1294849661688696932706114,
                                      0.1294849661688696932706114};

template <int D>
double gauss(const NurbsCurve<D>& c, double a, double b) {
  const double m = 0.5 * (a + b), h = 0.5 * (b - a);
  double s = 0.0;
  for (std::size_t i = 0; i < kX.size(); ++i) s += kW[i] * c.eval(m + h * kX[i]).d1.norm();
  return s * h;
}

template <int D>
double adaptive(const NurbsCurve<D>& c, double a, double b, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b);
  const double l = gauss(c, a, m), r = gauss(c, m, b);
  if (depth > 40 || std::abs(l + r - whole) <= tol) return l + r;
  return adaptive(c, a, m, l, 0.5 * tol, depth + 1) + adaptive(c, m, b, r, 0.5 * tol, depth + 1);
}

}  // namespace

template <int D>
double arc_length(const NurbsCurve<D>& c, double a, double b, double rel_tol) {
  // Per knot span: |C'| is smooth inside a span, only its derivatives jump at knots.
  const auto& U = c.knots();
  double total = 0.0;
  const double tol = rel_tol * c.size();
  for (std::size_t k = 0; k + 1 < U.size(); ++k) {
    const double lo = std::max(a, U[k]), hi = std::min(b, U[k + 1]);
    if (hi > lo) total += adaptive(c, lo, hi, gauss(c, lo, hi), tol, 0);
  }
  return total;
}

template <int D>
CurveSamples<D> sample_arc_length(const NurbsCurve<D>& c, double dx) {
  // Table of cumulative length at fine parameter breaks, then Newton (ds/dt = |C'|,
  // bracketed by bisection) for each target length.
  std::vector<double> tb{c.t0()}, sb{0.0};
  const auto& U = c.knots();
  for (std::size_t k = 0; k + 1 < U.size(); ++k) {
    const double lo = std::max(c.t0(), U[k]), hi = std::min(c.t1(), U[k + 1]);
    if (!(hi > lo)) continue;
    constexpr int kSub = 8;
    for (int i = 1; i <= kSub; ++i) {
      const double t = lo + (hi - lo) * i / kSub;
      sb.push_back(sb.back() + arc_length(c, tb.back(), t));
      tb.push_back(t);
    }
  }
  const double L = sb.back();
  const int segs = std::max(1, static_cast<int>(std::lround(L / dx)));
  CurveSamples<D> out;
  out.spacing = L / segs;
  const int count = c.closed() ? segs : segs + 1;
  for (int k = 0; k < count; ++k) {
    const double s = L * k / segs;
    std::size_t i = std::upper_bound(sb.begin(), sb.end(), s) - sb.begin();
    i = std::clamp<std::size_t>(i, 1, sb.size() - 1);
    double lo = tb[i - 1], hi = tb[i],
           t = lo + (hi - lo) * (s - sb[i - 1]) / std::max(sb[i] - sb[i - 1], 1e-300);
    for (int it = 0; it < 60; ++it) {
      const double f = sb[i - 1] + arc_length(c, tb[i - 1], t) - s;
      if (std::abs(f) <= 1e-12 * std::max(L, 1e-300)) break;
      (f > 0 ? hi : lo) = t;
      const double t_new = t - f / c.eval(t).d1.norm();
      t = (t_new > lo && t_new < hi) ? t_new : 0.5 * (lo + hi);
    }
    out.points.push_back(c.point(t));
    out.params.push_back(t);
  }
  return out;
}

SurfaceSamples sample_surface(const NurbsSurface& s, double dx) {
  // Parameter distribution along u from the mean chord length of a few u iso-curves
  // (and likewise along v).
  constexpr int kFine = 256, kIso = 5;
  const auto distribution = [&](bool along_u) {
    std::vector<double> cum(kFine + 1, 0.0);
    const double a0 = along_u ? s.u0() : s.v0(), a1 = along_u ? s.u1() : s.v1();
    const double b0 = along_u ? s.v0() : s.u0(), b1 = along_u ? s.v1() : s.u1();
    for (int l = 0; l < kIso; ++l) {
      const double b = b0 + (b1 - b0) * (l + 0.5) / kIso;
      Vec3d prev = along_u ? s.point(a0, b) : s.point(b, a0);
      for (int i = 1; i <= kFine; ++i) {
        const double a = a0 + (a1 - a0) * i / kFine;
        const Vec3d p = along_u ? s.point(a, b) : s.point(b, a);
        cum[i] += (p - prev).norm() / kIso;
        prev = p;
      }
    }
    for (int i = 1; i <= kFine; ++i) cum[i] += cum[i - 1];
    const int n = std::max(1, static_cast<int>(std::lround(cum[kFine] / dx)));
    std::vector<double> params;
    for (int k = 0; k <= n; ++k) {
      const double target = cum[kFine] * k / n;
      int i = static_cast<int>(std::upper_bound(cum.begin(), cum.end(), target) - cum.begin());
      i = std::clamp(i, 1, kFine);
      const double f = (target - cum[i - 1]) / std::max(cum[i] - cum[i - 1], 1e-300);
      params.push_back(a0 + (a1 - a0) * (i - 1 + std::clamp(f, 0.0, 1.0)) / kFine);
    }
    return params;
  };
  const std::vector<double> us = distribution(true), vs = distribution(false);
  SurfaceSamples out;
  for (double u : us)
    for (double v : vs) {
      out.points.push_back(s.point(u, v));
      out.params.push_back({u, v});
    }
  return out;
}

template double arc_length<2>(const NurbsCurve<2>&, double, double, double);
template double arc_length<3>(const NurbsCurve<3>&, double, double, double);
template CurveSamples<2> sample_arc_length<2>(const NurbsCurve<2>&, double);
template CurveSamples<3> sample_arc_length<3>(const NurbsCurve<3>&, double);

}  // namespace curvsph::nurbs
