// The Schäfer & Turek benchmark figures (analysis/cylinder_benchmark.hpp) on synthetic
// histories whose answers are known in closed form: sines of given frequency, amplitude and
// phase (with and without noise, on uneven sampling), a decaying transient, and the force
// coefficient of a hand-computed force.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "curvsph/analysis/cylinder_benchmark.hpp"

namespace curvsph {
namespace {

constexpr double pi = std::numbers::pi;

template <class F>
Signal sample(F f, double t0, double t1, double dt) {
  Signal s;
  const auto n = static_cast<long>(std::lround((t1 - t0) / dt));
  for (long k = 0; k <= n; ++k) {
    const double t = t0 + static_cast<double>(k) * dt;
    s.t.push_back(t);
    s.v.push_back(f(t));
  }
  return s;
}

TEST(CylinderBenchmark, ForceCoefficientOfTheBenchmarkScales) {
  // 2D-1: U_m = 0.3, mean 0.2; D = 0.1, rho = 1: dynamic pressure times D = 0.5 * 0.04 * 0.1.
  EXPECT_DOUBLE_EQ(parabolic_mean_speed(0.3), 0.2);
  EXPECT_NEAR(force_coefficient(0.0111590705, 1.0, 0.2, 0.1), 5.57953525, 1e-8);
  // 2D-2: U_m = 1.5, mean 1; a force of 0.5 * 1 * 1 * 0.1 * 3.23 gives C = 3.23.
  EXPECT_NEAR(force_coefficient(0.1615, 1.0, parabolic_mean_speed(1.5), 0.1), 3.23, 1e-12);
}

TEST(CylinderBenchmark, WindowStatsOfASineOnUnevenSampling) {
  // a + b sin(2 pi t) over whole periods: mean a, standard deviation b / sqrt(2), whatever
  // the sampling (here denser in the first half of each period).
  Signal s;
  for (int k = 0; k <= 4000; ++k) {
    const double u = k / 1000.0, frac = u - std::floor(u);
    const double t = std::floor(u) + (frac < 0.5 ? 0.5 * frac : 0.25 + 1.5 * (frac - 0.5));
    s.t.push_back(t);
    s.v.push_back(2.0 + 0.3 * std::sin(2 * pi * t));
  }
  const WindowStats w = window_stats(s, 1.0, 3.0);
  EXPECT_NEAR(w.mean, 2.0, 1e-6);
  EXPECT_NEAR(w.std, 0.3 / std::sqrt(2.0), 1e-5);
  EXPECT_NEAR(w.max, 2.3, 1e-5);
  EXPECT_NEAR(w.min, 1.7, 1e-5);
  EXPECT_THROW(window_stats(s, 10, 11), std::invalid_argument);
}

TEST(CylinderBenchmark, SteadyFigureMeasuresTheDrift) {
  // v = 5 + exp(-t): over [2, 4] the mean is 5 + (e^-2 - e^-4) / 2 and the second half's mean
  // minus the first's is (e^-3 - e^-4) - (e^-2 - e^-3). Trapezoidal rule, step 1e-3: error
  // dt^2 / 12 |v''| ~ 1e-8.
  const Signal s = sample([](double t) { return 5 + std::exp(-t); }, 0, 4, 1e-3);
  const SteadyFigure f = steady_figure(s, 2, 4);
  EXPECT_NEAR(f.stats.mean, 5 + (std::exp(-2) - std::exp(-4)) / 2, 1e-7);
  EXPECT_NEAR(f.drift, 2 * std::exp(-3) - std::exp(-4) - std::exp(-2), 1e-7);
}

TEST(CylinderBenchmark, StandardErrorByBatchMeans) {
  // Over [0, 4] in 4 batches the signal is constant per batch: 1, 3, 2, 6 (plus a sine of
  // whole periods within each batch, which averages out). Batch means 1, 3, 2, 6: mean 3,
  // sample variance (4 + 0 + 1 + 9) / 3 = 14 / 3, standard error sqrt(14 / 3 / 4).
  const double level[] = {1, 3, 2, 6};
  Signal s;
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i <= 1000; ++i) {
      const double t = k + (i == 0 ? 1e-9 : i * 1e-3 - (i == 1000 ? 1e-9 : 0));
      s.t.push_back(t);
      s.v.push_back(level[k] + 0.5 * std::sin(2 * pi * 5 * t));
    }
  const SteadyFigure f = steady_figure(s, 0, 4, 4);
  EXPECT_NEAR(f.stats.mean, 3, 1e-5);
  EXPECT_NEAR(f.standard_error, std::sqrt(14.0 / 3 / 4), 1e-4);
}

TEST(CylinderBenchmark, SettlingTimeOfADecay) {
  // 5 + exp(-t) stays within 1 % of 5 from exp(-t) = 0.05, t = ln 20, on (the sample after).
  const Signal s = sample([](double t) { return 5 + std::exp(-t); }, 0, 6, 1e-3);
  EXPECT_NEAR(settling_time(s, 5, 0.01), std::log(20.0), 1.1e-3);
  EXPECT_TRUE(std::isnan(settling_time(s, 4, 0.01)));  // never within 1 % of 4
}

TEST(CylinderBenchmark, RunningMeanDampsASineBySinc) {
  const double T = 0.4, w = T / 5;
  const Signal s = sample([&](double t) { return std::cos(2 * pi * t / T); }, 0, 4, 1e-4);
  const Signal r = running_mean(s, w);
  const double gain = std::sin(pi * w / T) / (pi * w / T);
  // The window holds the samples within +-w/2, so its length is w to a sampling step dt =
  // 1e-4, which moves the mean by |d gain / dw| dt ~ 2e-4.
  EXPECT_NEAR(sample_at(r, 2.0), gain, 3e-4);  // at a crest
  EXPECT_NEAR(sample_at(r, 2.1), 0.0, 3e-4);   // at a zero
}

// 2D-2-like histories: lift A sin(2 pi f t + phi), drag C0 + B sin(4 pi f t + psi) (twice the
// frequency, as in vortex shedding), dp = P0 + Q sin(2 pi f t + phi + chi). At the lift
// maximum the lift's phase is pi/2; half a period later it is 3 pi / 2, where
// dp = P0 + Q sin(3 pi / 2 + chi) = P0 - Q cos(chi).
struct Shedding {
  double f = 3.0, A = 1.0, phi = 0.7, C0 = 3.1, B = 0.13, psi = -0.4, P0 = 2.4, Q = 0.2, chi = 0.5;
};

TEST(CylinderBenchmark, PeriodicFiguresOfCleanSines) {
  const Shedding m;
  const double dt = 0.01;  // the 2D-2 case's output interval: 33 samples per period
  const Signal cl =
      sample([&](double t) { return m.A * std::sin(2 * pi * m.f * t + m.phi); }, 0, 8, dt);
  const Signal cd =
      sample([&](double t) { return m.C0 + m.B * std::sin(4 * pi * m.f * t + m.psi); }, 0, 8, dt);
  const Signal dp = sample(
      [&](double t) { return m.P0 + m.Q * std::sin(2 * pi * m.f * t + m.phi + m.chi); }, 0, 8, dt);
  const PeriodicFigures p = periodic_figures(cl, cd, dp, 2, 7, 0);
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.periods, 14);  // 15 upward crossings in 5 s at 3 Hz
  EXPECT_NEAR(p.frequency, m.f, 1e-4);
  EXPECT_LT(p.period_spread, 1e-3);
  EXPECT_NEAR(p.cl_max, m.A, 1e-3);
  EXPECT_NEAR(p.cl_min, -m.A, 1e-3);
  EXPECT_NEAR(p.cd_max, m.C0 + m.B, 1e-3);
  EXPECT_NEAR(p.dp_half_period, m.P0 - m.Q * std::cos(m.chi), 2e-3);
}

TEST(CylinderBenchmark, PeriodicFiguresThroughNoise) {
  // The same histories with Gaussian noise of a fifth of the lift amplitude (SPH's acoustic
  // and particle noise): the hysteresis on the lift's running mean over a twentieth of the
  // period keeps the count of crossings, the per-period harmonic fits keep the maxima within
  // 2 % (the largest raw sample of a period would be about 0.5 too high).
  const Shedding m;
  std::mt19937 gen(12345);
  std::normal_distribution<double> noise(0.0, 0.2);
  const double dt = 0.002;
  const Signal cl = sample(
      [&](double t) { return m.A * std::sin(2 * pi * m.f * t + m.phi) + noise(gen); }, 0, 12, dt);
  const Signal cd =
      sample([&](double t) { return m.C0 + m.B * std::sin(4 * pi * m.f * t + m.psi) + noise(gen); },
             0, 12, dt);
  const Signal dp = sample(
      [&](double t) {
        return m.P0 + m.Q * std::sin(2 * pi * m.f * t + m.phi + m.chi) + noise(gen);
      },
      0, 12, dt);
  const PeriodicFigures p = periodic_figures(cl, cd, dp, 2, 12, 1 / (20 * m.f));
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.periods, 29);
  EXPECT_NEAR(p.frequency, m.f, 0.005 * m.f);
  EXPECT_NEAR(p.cl_max, m.A, 0.02 * m.A);
  EXPECT_NEAR(p.cd_max, m.C0 + m.B, 0.02 * m.C0);
  EXPECT_NEAR(p.dp_half_period, m.P0 - m.Q * std::cos(m.chi), 0.02 * m.P0);
}

TEST(CylinderBenchmark, PeriodicFiguresNeedTwoPeriods) {
  // A steady lift with noise has no band crossings in a periodic pattern worth the name; a
  // single period is not enough for a frequency.
  const Signal cl = sample([](double t) { return std::sin(2 * pi * 0.3 * t); }, 0, 4, 0.01);
  const PeriodicFigures p = periodic_figures(cl, cl, cl, 0, 4, 0);
  EXPECT_FALSE(p.found);
}

}  // namespace
}  // namespace curvsph
