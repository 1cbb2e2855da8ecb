// Wendland C2 kernel (DESIGN.md §4): normalisation and second moment by radial quadrature,
// derivative against finite differences, compact support.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "curvsph/kernels/wendland.hpp"

namespace curvsph {
namespace {

// Gauss–Legendre nodes and weights on [-1, 1] by Newton iteration on P_n (independent of
// any kernel code). Exact for polynomials of degree <= 2n - 1.
template <class T>
void gauss_legendre(int n, std::vector<T>& x, std::vector<T>& w) {
  x.assign(n, 0);
  w.assign(n, 0);
  const T pi = std::numbers::pi_v<T>;
  for (int i = 0; i < n; ++i) {
    T z = std::cos(pi * (i + T(0.75)) / (n + T(0.5)));
    T dp = 0;
    for (int it = 0; it < 100; ++it) {
      T p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const T p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const T dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 10 * std::numeric_limits<T>::epsilon()) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

// Composite Gauss–Legendre of f over [a, b] with `panels` panels of n nodes each.
template <class T, class F>
T integrate(F&& f, T a, T b, int panels = 8, int n = 12) {
  std::vector<T> x, w;
  gauss_legendre<T>(n, x, w);
  T sum = 0;
  const T width = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    const T lo = a + p * width, half = width / 2, mid = lo + half;
    for (int i = 0; i < n; ++i) sum += w[i] * half * f(mid + half * x[i]);
  }
  return sum;
}

// Surface measure of the unit sphere in D dimensions times r^(D-1).
template <class T>
T shell(int D, T r) {
  const T pi = std::numbers::pi_v<T>;
  return D == 2 ? 2 * pi * r : 4 * pi * r * r;
}

// The kernel written out from DESIGN.md §4 in long double (not the library's code).
long double design_kernel(int D, long double r, long double h) {
  const long double pi = std::numbers::pi_v<long double>;
  const long double q = r / h;
  if (q >= 2) return 0;
  const long double alpha = D == 2 ? 7.0L / (4 * pi * h * h) : 21.0L / (16 * pi * h * h * h);
  return alpha * std::pow(1 - q / 2, 4) * (2 * q + 1);
}

template <int D>
double moment(const WendlandC2<D>& W, int power) {
  return integrate<double>(
      [&](double r) { return std::pow(r, power) * W.value(r) * shell<double>(D, r); }, 0.0,
      2 * W.h);
}

template <int D>
void check_normalisation(double h) {
  const WendlandC2<D> W(h);
  EXPECT_NEAR(moment(W, 0), 1.0, 1e-13) << "D = " << D << ", h = " << h;
  // Nothing is missed outside the support: the integral to 3h is the same.
  const double wide =
      integrate<double>([&](double r) { return W.value(r) * shell<double>(D, r); }, 0.0, 3 * h, 48);
  EXPECT_NEAR(wide, 1.0, 1e-12);
}

TEST(Kernel, Normalisation2D) {
  for (double h : {1.0, 0.013, 2.7}) check_normalisation<2>(h);
}
TEST(Kernel, Normalisation3D) {
  for (double h : {1.0, 0.013, 2.7}) check_normalisation<3>(h);
}

template <int D>
void check_second_moment(double h, long double exact_over_h2) {
  const WendlandC2<D> W(h);
  // Reference: the formula of DESIGN.md §4 integrated in long double with more nodes.
  const long double ref = integrate<long double>(
      [&](long double r) { return r * r * design_kernel(D, r, h) * shell<long double>(D, r); },
      0.0L, 2.0L * h, 16, 20);
  EXPECT_NEAR(static_cast<double>(ref / (h * h)), static_cast<double>(exact_over_h2), 1e-15);
  EXPECT_NEAR(moment(W, 2) / (h * h), static_cast<double>(ref / (h * h)), 1e-13);
}

// Closed forms (exact integration of the polynomial): 5/9 h^2 in 2-D, 4/5 h^2 in 3-D.
TEST(Kernel, SecondMoment2D) {
  for (double h : {1.0, 0.02}) check_second_moment<2>(h, 5.0L / 9.0L);
}
TEST(Kernel, SecondMoment3D) {
  for (double h : {1.0, 0.02}) check_second_moment<3>(h, 4.0L / 5.0L);
}

template <int D>
void check_derivatives(double h) {
  const WendlandC2<D> W(h);
  const double eps = 1e-5 * h;
  for (int k = 1; k < 200; ++k) {
    const double r = 2 * h * k / 200.0;
    if (std::abs(r - 2 * h) < 2 * eps) continue;
    const double fd = (W.value(r + eps) - W.value(r - eps)) / (2 * eps);
    const double scale = W.alpha / h;  // magnitude of dW/dr
    EXPECT_NEAR(W.derivative(r), fd, 1e-8 * scale) << "r/h = " << r / h;
    EXPECT_NEAR(W.gradient_factor(r) * r, W.derivative(r), 1e-14 * scale) << "r/h = " << r / h;
    EXPECT_LE(W.derivative(r), 0.0);
  }
  // At r = 0 the slope vanishes and the gradient factor stays finite and negative.
  EXPECT_EQ(W.derivative(0.0), 0.0);
  EXPECT_LT(W.gradient_factor(0.0), 0.0);
  EXPECT_TRUE(std::isfinite(W.gradient_factor(0.0)));
  // gradient_factor(r) -> its r = 0 value (it is smooth there).
  EXPECT_NEAR(W.gradient_factor(1e-6 * h), W.gradient_factor(0.0),
              1e-5 * std::abs(W.gradient_factor(0.0)));
}

TEST(Kernel, DerivativeMatchesFiniteDifference2D) {
  check_derivatives<2>(0.37);
}
TEST(Kernel, DerivativeMatchesFiniteDifference3D) {
  check_derivatives<3>(1.9);
}

template <int D>
void check_support(double h) {
  const WendlandC2<D> W(h);
  EXPECT_EQ(W.support, 2 * h);
  EXPECT_EQ(W.value(2 * h), 0.0);
  EXPECT_EQ(W.derivative(2 * h), 0.0);
  EXPECT_EQ(W.gradient_factor(2 * h), 0.0);
  for (double f : {1.0000001, 1.5, 3.0, 1e6}) {
    EXPECT_EQ(W.value(2 * h * f), 0.0);
    EXPECT_FALSE(std::signbit(W.value(2 * h * f)));  // +0: sums stay sign-exact
    EXPECT_EQ(W.derivative(2 * h * f), 0.0);
    EXPECT_EQ(W.gradient_factor(2 * h * f), 0.0);
  }
  // Just inside the support the kernel is positive, tiny and continuous with zero.
  const double r = 2 * h * (1 - 1e-4);
  EXPECT_GT(W.value(r), 0.0);
  EXPECT_LT(W.value(r), 1e-14 * W.alpha);
  EXPECT_EQ(W.value(0.0), W.value_at_zero());
  EXPECT_DOUBLE_EQ(W.value_at_zero(), static_cast<double>(design_kernel(D, 0.0L, h)));
  // Positive and strictly decreasing on [0, 2h).
  double prev = W.value(0.0);
  for (int k = 1; k < 100; ++k) {
    const double v = W.value(2 * h * k / 100.0);
    EXPECT_GT(v, 0.0);
    EXPECT_LT(v, prev);
    prev = v;
  }
}

TEST(Kernel, CompactSupport2D) {
  check_support<2>(0.5);
}
TEST(Kernel, CompactSupport3D) {
  check_support<3>(0.013);
}

TEST(Kernel, ValueMatchesDesignFormula) {
  for (double h : {0.1, 1.3}) {
    const WendlandC2<2> W2(h);
    const WendlandC2<3> W3(h);
    for (int k = 0; k <= 50; ++k) {
      const double r = 2.2 * h * k / 50.0;
      EXPECT_NEAR(W2.value(r), static_cast<double>(design_kernel(2, r, h)), 1e-14 * W2.alpha);
      EXPECT_NEAR(W3.value(r), static_cast<double>(design_kernel(3, r, h)), 1e-14 * W3.alpha);
    }
  }
}

}  // namespace
}  // namespace curvsph
