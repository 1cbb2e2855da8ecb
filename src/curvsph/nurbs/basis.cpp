#include "curvsph/nurbs/basis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "curvsph/core/error.hpp"

namespace curvsph::nurbs {

void validate_knots(const std::vector<double>& knots, int degree, int n_ctrl,
                    const InputContext& ctx, const std::string& knots_key) {
  const std::string key = ctx.key(knots_key);
  if (degree < 1 || degree > kMaxDegree)
    throw InputError(ctx.file, ctx.key("degree"),
                     fmt::format("degree {} outside 1..{}", degree, kMaxDegree));
  if (n_ctrl < degree + 1)
    throw InputError(ctx.file, ctx.key("control_points"),
                     fmt::format("{} control points, a degree-{} NURBS needs at least {}", n_ctrl,
                                 degree, degree + 1));
  const std::size_t expected = static_cast<std::size_t>(n_ctrl + degree + 1);
  if (knots.size() != expected)
    throw InputError(
        ctx.file, key,
        fmt::format("{} knots, expected control points + degree + 1 = {}", knots.size(), expected));
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i]))
      throw InputError(ctx.file, key, fmt::format("knot {} is not finite", i));
    if (i > 0 && knots[i] < knots[i - 1])
      throw InputError(
          ctx.file, key,
          fmt::format("knots decrease at index {} ({} < {})", i, knots[i], knots[i - 1]));
  }
  // Interior multiplicity above the degree would make the curve discontinuous (P&T §2.2);
  // the end values may repeat degree + 1 times (clamped knots).
  const std::size_t p = static_cast<std::size_t>(degree);
  const double lo = knots[p], hi = knots[expected - p - 1];
  for (std::size_t i = 0; i < expected;) {
    std::size_t j = i;
    while (j + 1 < expected && knots[j + 1] == knots[i]) ++j;
    const std::size_t mult = j - i + 1;
    if (knots[i] > lo && knots[i] < hi && mult > p)
      throw InputError(
          ctx.file, key,
          fmt::format("interior knot {} has multiplicity {} > degree {}", knots[i], mult, degree));
    if (mult > p + 1)
      throw InputError(ctx.file, key,
                       fmt::format("knot {} has multiplicity {} > degree + 1", knots[i], mult));
    i = j + 1;
  }
  if (!(knots[p] < knots[expected - p - 1]))
    throw InputError(ctx.file, key, "empty parameter range (knots[degree] == knots[n])");
  // The basis functions' derivatives scale as 1/span (P&T eq. 2.9, twice for the curvature):
  // a span of 1e-300 overflows them, and a range far below the knots' magnitude leaves the
  // parameter unresolved in double precision. Spans are kept above 1e-12 of the range.
  constexpr double kMinRelativeSpan = 1e-12, kMinRange = 1e-100;
  const double range = hi - lo;
  if (range < kMinRange || range < kMinRelativeSpan * std::max(std::abs(lo), std::abs(hi)))
    throw InputError(ctx.file, key,
                     fmt::format("parameter range [{}, {}] is too narrow (at least 1e-100 and "
                                 "1e-12 of the knots' magnitude)",
                                 lo, hi));
  for (std::size_t i = 0; i + 1 < expected; ++i) {
    const double span = knots[i + 1] - knots[i];
    if (span > 0 && span < kMinRelativeSpan * range)
      throw InputError(ctx.file, key,
                       fmt::format("knot span {} between indices {} and {} is below 1e-12 of the "
                                   "parameter range {} (repeat the knot instead)",
                                   span, i, i + 1, range));
  }
}

int find_span(int n, int p, double u, const double* U) {
  if (u >= U[n + 1]) {
    // End of the range: the last non-empty span (A2.1 special case, robust to end blocks).
    int s = n;
    while (s > p && U[s] >= U[n + 1]) --s;
    return s;
  }
  if (u <= U[p]) {
    int s = p;
    while (s < n && U[s + 1] <= U[p]) ++s;
    return s;
  }
  int low = p, high = n + 1;
  int mid = (low + high) / 2;
  while (u < U[mid] || u >= U[mid + 1]) {
    if (u < U[mid])
      high = mid;
    else
      low = mid;
    mid = (low + high) / 2;
  }
  return mid;
}

void basis_funs(int span, double u, int p, const double* U, double* N) {
  double left[kMaxOrder], right[kMaxOrder];
  N[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[span + 1 - j];
    right[j] = U[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
}

void ders_basis_funs(int span, double u, int p, int nd, const double* U, double ders[][kMaxOrder]) {
  double ndu[kMaxOrder][kMaxOrder];
  double a[2][kMaxOrder];
  double left[kMaxOrder], right[kMaxOrder];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[span + 1 - j];
    right[j] = U[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;  // upper triangle: basis functions
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
  const int nk = std::min(nd, p);  // derivatives above the degree vanish
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= nk; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = d;
      std::swap(s1, s2);
    }
  }
  int r = p;
  for (int k = 1; k <= nk; ++k) {
    for (int j = 0; j <= p; ++j) ders[k][j] *= r;
    r *= (p - k);
  }
  for (int k = p + 1; k <= nd; ++k)
    for (int j = 0; j <= p; ++j) ders[k][j] = 0.0;
}

}  // namespace curvsph::nurbs
