// The in-line force fits of `validate oscillating_cylinder` (analysis/oscillating_force.hpp) on
// synthetic signals whose harmonics and Morison coefficients are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "curvsph/analysis/oscillating_force.hpp"

namespace curvsph {
namespace {

constexpr double kPi = std::numbers::pi;

// Dütsch et al.'s case in the units of cases/oscillating_cylinder_dutsch.yaml.
InlineOscillation dutsch() {
  return {0.1, 1.0, 0.1, 0.2};
}

TEST(OscillatingForce, MotionAndMorisonHandValues) {
  const InlineOscillation o = dutsch();
  const MorisonCoefficients c{2.09, 1.45};
  const double T = 5.0, w = 2 * kPi / T;
  EXPECT_NEAR(o.omega(), w, 1e-15);
  // t = 0: moving towards -x at full speed, no acceleration: pure drag, pushing towards +x.
  EXPECT_NEAR(o.velocity(0), -0.1, 1e-16);
  EXPECT_NEAR(o.acceleration(0), 0, 1e-16);
  EXPECT_NEAR(morison_force(o, c, 0), 0.5 * 1.0 * 0.1 * 2.09 * 0.01, 1e-15);
  // t = T/4: at rest, accelerating towards +x at U omega: pure inertia, towards -x.
  EXPECT_NEAR(o.velocity(T / 4), 0, 1e-16);
  EXPECT_NEAR(morison_force(o, c, T / 4), -1.0 * kPi * 0.01 / 4 * 1.45 * 0.1 * w, 1e-15);
  // In the paper's unit rho U^2 D: C_d / 2 at t = 0.
  EXPECT_NEAR(morison_force(o, c, 0) / o.force_scale(), 2.09 / 2, 1e-12);
}

TEST(OscillatingForce, FirstHarmonicOfMorisonMatchesFourierIntegrals) {
  // The drag term (1/2) rho D C_d U^2 cos|cos| has the cosine coefficient
  // (1/2) rho D C_d U^2 * 8 / (3 pi) (integral of cos^2 |cos| over a period: 8/3); the inertia
  // term is a pure sine, -rho (pi D^2 / 4) C_i U omega.
  const InlineOscillation o = dutsch();
  const MorisonCoefficients c{2.09, 1.45};
  // |cos| cos is not smooth where u = 0: its harmonics decay as k^-3, and those above n/2 of the
  // n = 2000 samples alias onto the first at about 1e-12 of it.
  const FirstHarmonic h = morison_first_harmonic(o, c);
  const double a = 0.5 * 1.0 * 0.1 * 2.09 * 0.01 * 8 / (3 * kPi);
  const double b = -kPi * 0.01 / 4 * 1.45 * 0.1 * o.omega();
  EXPECT_NEAR(h.a, a, 1e-9 * std::abs(a));
  EXPECT_NEAR(h.b, b, 1e-9 * std::abs(b));
  EXPECT_NEAR(h.mean, 0, 1e-15);
  EXPECT_NEAR(h.amplitude(), std::hypot(a, b), 1e-9 * std::abs(b));
  EXPECT_NEAR(h.phase(), std::atan2(b, a), 1e-9);
}

TEST(OscillatingForce, FirstHarmonicFitRecoversAmplitudeAndPhase) {
  // mean + A cos(omega t - phi) + a third harmonic, sampled evenly over whole periods of the
  // window (the discrete sines and cosines are orthogonal there), with a start-up transient
  // before the window that the fit must ignore.
  const double w = 2 * kPi / 5.0, A = 0.0017, phi = -0.97, m = 2e-5;
  std::vector<double> t, f;
  for (int k = 0; k <= 4000; ++k) {
    const double s = 20.0 * k / 4000;
    t.push_back(s);
    f.push_back(s < 10 ? 1.0 : m + A * std::cos(w * s - phi) + 0.3 * A * std::cos(3 * w * s));
  }
  const FirstHarmonic h = fit_first_harmonic(t, f, w, 10.0, 20.0 - 1e-9);
  EXPECT_NEAR(h.amplitude(), A, 1e-12);
  EXPECT_NEAR(h.phase(), phi, 1e-9);
  EXPECT_NEAR(h.mean, m, 1e-12);
}

TEST(OscillatingForce, MorisonFitRecoversCoefficientsFromUnevenNoisySamples) {
  // The Morison signal of known coefficients at random times over two periods, plus a
  // zero-mean noise: the fit returns the coefficients to within the noise's share.
  const InlineOscillation o = dutsch();
  const MorisonCoefficients c{2.3, 1.2};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> when(10.0, 20.0);
  std::normal_distribution<double> noise(0.0, 0.02 * o.force_scale());
  std::vector<double> t, f, f_noisy;
  for (int k = 0; k < 3000; ++k) {
    t.push_back(when(rng));
    f.push_back(morison_force(o, c, t.back()));
    f_noisy.push_back(f.back() + noise(rng));
  }
  const MorisonCoefficients exact = fit_morison(t, f, o, 10.0, 20.0);
  EXPECT_NEAR(exact.cd, 2.3, 1e-10);
  EXPECT_NEAR(exact.ci, 1.2, 1e-10);
  const MorisonCoefficients fit = fit_morison(t, f_noisy, o, 10.0, 20.0);
  EXPECT_NEAR(fit.cd, 2.3, 0.02);
  EXPECT_NEAR(fit.ci, 1.2, 0.02);
  EXPECT_GT(std::abs(fit.cd - 2.3) + std::abs(fit.ci - 1.2), 0);  // the noise did act
}

TEST(OscillatingForce, PhaseDifferenceWrapsIntoOneTurn) {
  EXPECT_NEAR(phase_difference(0.1, -0.1), 0.2, 1e-15);
  EXPECT_NEAR(phase_difference(3.0, -3.0), 6.0 - 2 * kPi, 1e-15);
  EXPECT_NEAR(phase_difference(-3.0, 3.0), 2 * kPi - 6.0, 1e-15);
  EXPECT_NEAR(phase_difference(kPi, -kPi), 0, 1e-15);
  EXPECT_NEAR(phase_difference(-kPi / 2, kPi), kPi / 2, 1e-15);
}

TEST(OscillatingForce, TooFewSamplesInTheWindowThrow) {
  const std::vector<double> t = {0, 1, 2, 3}, f = {0, 1, 0, -1};
  EXPECT_THROW(fit_first_harmonic(t, f, 1.0, 2.5, 10), std::invalid_argument);
  EXPECT_THROW(fit_morison(t, {0, 1}, dutsch(), 0, 3), std::invalid_argument);
}

}  // namespace
}  // namespace curvsph
