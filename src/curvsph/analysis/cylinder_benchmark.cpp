#include "curvsph/analysis/cylinder_benchmark.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace curvsph {
namespace {

// Indices [first, last) of the samples with from <= t <= to.
std::pair<std::size_t, std::size_t> window(const Signal& s, double from, double to) {
  const auto a = std::lower_bound(s.t.begin(), s.t.end(), from);
  const auto b = std::upper_bound(s.t.begin(), s.t.end(), to);
  return {static_cast<std::size_t>(a - s.t.begin()), static_cast<std::size_t>(b - s.t.begin())};
}

// One period's least-squares fit v(t) ~ c0 + sum_k (a_k cos k w t + b_k sin k w t), k = 1..K,
// w = 2 pi / (t1 - t0), over the samples in [t0, t1]: a periodic curve whose extrema do not
// follow the noise on single samples (zero-mean noise moves the coefficients by its own
// projection only, O(sigma / sqrt(samples)), while the largest raw sample is biased upwards by
// about two sigma). The lift of vortex shedding is nearly a sine; its drag oscillates at
// twice the frequency; K = 3 holds both with their first overtones.
struct PeriodFit {
  double t0 = 0, w = 0;
  Eigen::VectorXd c;  // c0, a1, b1, a2, b2, ...
  double operator()(double t) const {
    double v = c(0);
    for (Eigen::Index k = 1; 2 * k < c.size(); ++k)
      v += c(2 * k - 1) * std::cos(k * w * (t - t0)) + c(2 * k) * std::sin(k * w * (t - t0));
    return v;
  }
};

constexpr int kHarmonics = 3;

// NaN coefficients when the period holds too few samples for the fit.
PeriodFit fit_period(const Signal& s, double t0, double t1) {
  const auto [a, b] = window(s, t0, t1);
  PeriodFit f{t0, 2 * std::numbers::pi / (t1 - t0),
              Eigen::VectorXd::Constant(2 * kHarmonics + 1, std::nan(""))};
  const auto n = static_cast<Eigen::Index>(b - a), m = f.c.size();
  if (n < 2 * m) return f;
  Eigen::MatrixXd A(n, m);
  Eigen::VectorXd y(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = f.w * (s.t[a + static_cast<std::size_t>(i)] - t0);
    A(i, 0) = 1;
    for (Eigen::Index k = 1; 2 * k < m; ++k) {
      A(i, 2 * k - 1) = std::cos(static_cast<double>(k) * x);
      A(i, 2 * k) = std::sin(static_cast<double>(k) * x);
    }
    y(i) = s.v[a + static_cast<std::size_t>(i)];
  }
  f.c = A.colPivHouseholderQr().solve(y);
  return f;
}

// The extremum (sign = 1: maximum, -1: minimum) of a fitted period and its time, on a grid of
// 2000 points over the period: the value is right to (pi / 2000)^2 / 2 ~ 1e-6 of the
// amplitude.
std::pair<double, double> extremum(const PeriodFit& f, double sign) {
  constexpr int n = 2000;
  const double T = 2 * std::numbers::pi / f.w;
  double best_t = f.t0, best = sign * f(f.t0);
  for (int i = 1; i < n; ++i) {
    const double t = f.t0 + T * i / n, v = sign * f(t);
    if (v > best) best = v, best_t = t;
  }
  return {best_t, sign * best};
}

}  // namespace

double force_coefficient(double force, double rho, double u_mean, double diameter) {
  return 2 * force / (rho * u_mean * u_mean * diameter);
}

double parabolic_mean_speed(double u_max) {
  return 2 * u_max / 3;
}

WindowStats window_stats(const Signal& s, double from, double to) {
  const auto [a, b] = window(s, from, to);
  if (b < a + 2) throw std::invalid_argument("window_stats: fewer than two samples in the window");
  WindowStats w;
  w.samples = b - a;
  w.min = w.max = s.v[a];
  double integral = 0;
  for (std::size_t i = a + 1; i < b; ++i) {
    integral += 0.5 * (s.v[i] + s.v[i - 1]) * (s.t[i] - s.t[i - 1]);
    w.min = std::min(w.min, s.v[i]);
    w.max = std::max(w.max, s.v[i]);
  }
  const double span = s.t[b - 1] - s.t[a];
  w.mean = integral / span;
  double square = 0;
  for (std::size_t i = a + 1; i < b; ++i) {
    const double e0 = s.v[i - 1] - w.mean, e1 = s.v[i] - w.mean;
    square += 0.5 * (e0 * e0 + e1 * e1) * (s.t[i] - s.t[i - 1]);
  }
  w.std = std::sqrt(square / span);
  return w;
}

Signal running_mean(const Signal& s, double width) {
  if (width <= 0) return s;
  Signal r{s.t, s.v};
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    const auto [a, b] = window(s, s.t[i] - 0.5 * width, s.t[i] + 0.5 * width);
    if (b < a + 2) continue;
    r.v[i] = window_stats(s, s.t[a], s.t[b - 1]).mean;
  }
  return r;
}

SteadyFigure steady_figure(const Signal& s, double from, double to, int batches) {
  SteadyFigure f;
  f.stats = window_stats(s, from, to);
  const double mid = 0.5 * (from + to);
  f.drift = window_stats(s, mid, to).mean - window_stats(s, from, mid).mean;
  std::vector<double> means;
  for (int b = 0; b < batches; ++b)
    means.push_back(
        window_stats(s, from + (to - from) * b / batches, from + (to - from) * (b + 1) / batches)
            .mean);
  double mean = 0, var = 0;
  for (double m : means) mean += m / batches;
  for (double m : means) var += (m - mean) * (m - mean) / (batches - 1);
  f.standard_error = std::sqrt(var / batches);
  return f;
}

double settling_time(const Signal& s, double value, double tol) {
  double t = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = s.t.size(); i-- > 0;) {
    if (std::abs(s.v[i] - value) > tol * std::abs(value)) break;
    t = s.t[i];
  }
  return t;
}

double sample_at(const Signal& s, double t) {
  if (s.t.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (t <= s.t.front()) return s.v.front();
  if (t >= s.t.back()) return s.v.back();
  const auto k =
      static_cast<std::size_t>(std::upper_bound(s.t.begin(), s.t.end(), t) - s.t.begin());
  const double w = (t - s.t[k - 1]) / (s.t[k] - s.t[k - 1]);
  return (1 - w) * s.v[k - 1] + w * s.v[k];
}

PeriodicFigures periodic_figures(const Signal& cl, const Signal& cd, const Signal& dp, double from,
                                 double to, double smoothing) {
  PeriodicFigures f;
  const auto [a, b] = window(cl, from, to);
  if (b < a + 4) return f;
  const Signal scl = running_mean(cl, smoothing);
  const WindowStats w = window_stats(scl, from, to);
  const double lo = w.mean - 0.5 * w.std, hi = w.mean + 0.5 * w.std;
  std::vector<double> up;  // upward crossings of the mean
  int state = 0;           // -1 below the band, +1 above it, 0 not yet known
  double candidate = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = a + 1; k < b; ++k) {
    const double v0 = scl.v[k - 1], v1 = scl.v[k];
    if (v0 < w.mean && v1 >= w.mean)
      candidate = scl.t[k - 1] + (w.mean - v0) / (v1 - v0) * (scl.t[k] - scl.t[k - 1]);
    if (v1 < lo) {
      state = -1;
      candidate = std::numeric_limits<double>::quiet_NaN();
    } else if (v1 > hi) {
      if (state == -1 && !std::isnan(candidate)) up.push_back(candidate);
      state = 1;
    }
  }
  if (up.size() < 3) return f;
  f.found = true;
  f.periods = static_cast<int>(up.size()) - 1;
  f.frequency = f.periods / (up.back() - up.front());
  const double T = 1 / f.frequency;
  double var = 0;
  for (std::size_t i = 1; i < up.size(); ++i) var += std::pow(up[i] - up[i - 1] - T, 2);
  f.period_spread = std::sqrt(var / f.periods) / T;
  int fitted = 0;
  for (std::size_t i = 1; i < up.size(); ++i) {
    const PeriodFit fl = fit_period(cl, up[i - 1], up[i]), fd = fit_period(cd, up[i - 1], up[i]);
    const PeriodFit fp = fit_period(dp, up[i - 1], up[i]);
    if (!fl.c.allFinite() || !fd.c.allFinite() || !fp.c.allFinite()) continue;
    const auto [t_top, top] = extremum(fl, 1);
    f.cl_max += top;
    f.cl_min += extremum(fl, -1).second;
    f.cd_max += extremum(fd, 1).second;
    // Half a period after the lift maximum, on the periodic fit (it may lie in the next
    // period).
    f.dp_half_period += fp(t_top + 0.5 * (up[i] - up[i - 1]));
    ++fitted;
  }
  if (fitted == 0) {
    f.found = false;
    return f;
  }
  f.cl_max /= fitted;
  f.cl_min /= fitted;
  f.cd_max /= fitted;
  f.dp_half_period /= fitted;
  return f;
}

}  // namespace curvsph
