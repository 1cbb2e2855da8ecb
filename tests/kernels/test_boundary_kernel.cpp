#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "curvsph/kernels/boundary_kernel.hpp"
#include "curvsph/kernels/wendland.hpp"

using namespace curvsph;

namespace {

template <int D>
void check_ode(double h) {
  const BoundaryKernel<D> F(h);
  const WendlandC2<D> W(h);
  // F(2h) = 0 and F = 0 beyond; F_P + F_D = F inside; F_Pext continuous at 2h.
  EXPECT_NEAR(F.polynomial(2 * h) + F.singular(2 * h), 0.0, 1e-14 / std::pow(h, D));
  EXPECT_NEAR(F.value(2 * h), 0.0, 1e-12 / std::pow(h, D));
  EXPECT_EQ(BoundaryKernel<D>(1.0).value(2.0), 0.0);
  EXPECT_EQ(F.value(3 * h), 0.0);
  EXPECT_NEAR(F.polynomial_extended(2 * h * (1 - 1e-12)),
              F.polynomial_extended(2 * h * (1 + 1e-12)), 1e-9 / std::pow(h, D));
  // rho^(1-d) d(rho^d F)/d rho = W by central differences (4th order).
  for (double q = 0.05; q < 2.0; q += 0.0731) {
    const double r = q * h, e = 1e-3 * h;
    auto G = [&](double s) { return std::pow(s, D) * F.value(s); };
    const double dG = (-G(r + 2 * e) + 8 * G(r + e) - 8 * G(r - e) + G(r - 2 * e)) / (12 * e);
    EXPECT_NEAR(dG / std::pow(r, D - 1), W.value(r), 1e-8 * W.value(0)) << "q = " << q;
  }
  // Beyond the support the extended polynomial part cancels the singular part.
  EXPECT_NEAR(F.polynomial_extended(2.5 * h) + F.singular(2.5 * h), 0.0, 1e-15);
}

}  // namespace

TEST(BoundaryKernel, ZeroAtSupportAndOde2D) {
  check_ode<2>(1.0);
  check_ode<2>(0.013);
}
TEST(BoundaryKernel, ZeroAtSupportAndOde3D) {
  check_ode<3>(1.0);
  check_ode<3>(0.27);
}

TEST(BoundaryKernel, PolynomialAtZeroIsHalfKernelPeak) {
  // F_P(0) = W(0)/d: m(r) ~ W(0) V_d r^d for small r.
  EXPECT_NEAR(BoundaryKernel<2>(1.0).polynomial(0.0), WendlandC2<2>(1.0).value(0) / 2, 1e-15);
  EXPECT_NEAR(BoundaryKernel<3>(1.0).polynomial(0.0), WendlandC2<3>(1.0).value(0) / 3, 1e-15);
}
