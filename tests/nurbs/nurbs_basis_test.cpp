#include <gtest/gtest.h>

#include <random>

#include "curvsph/nurbs/basis.hpp"
#include "test_shapes.hpp"

using namespace curvsph;
using namespace curvsph::nurbs;

TEST(NurbsBasis, PartitionOfUnityAndNonNegative) {
  std::mt19937 rng(7);
  for (int p = 1; p <= 5; ++p) {
    const int n = p + 6;
    const std::vector<double> U = test::random_knots(rng, p, n);
    for (int k = 0; k <= 200; ++k) {
      const double u = k / 200.0;
      const int span = find_span(n - 1, p, u, U.data());
      ASSERT_LE(U[span], u);
      double N[kMaxOrder];
      basis_funs(span, u, p, U.data(), N);
      double sum = 0.0;
      for (int j = 0; j <= p; ++j) {
        EXPECT_GE(N[j], -1e-15);
        sum += N[j];
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
      double ders[3][kMaxOrder];
      ders_basis_funs(span, u, p, 2, U.data(), ders);
      double s1 = 0.0, s2 = 0.0;
      for (int j = 0; j <= p; ++j) {
        EXPECT_NEAR(ders[0][j], N[j], 1e-14);
        s1 += ders[1][j];
        s2 += ders[2][j];
      }
      EXPECT_NEAR(s1, 0.0, 1e-9);
      EXPECT_NEAR(s2, 0.0, 1e-7);
    }
  }
}

TEST(NurbsBasis, DerivativesMatchFiniteDifferences) {
  std::mt19937 rng(11);
  for (int p = 2; p <= 4; ++p) {
    const int n = p + 5;
    const std::vector<double> U = test::random_knots(rng, p, n);
    const auto full = [&](double u, std::vector<double>& out) {
      out.assign(n, 0.0);
      const int s = find_span(n - 1, p, u, U.data());
      double N[kMaxOrder];
      basis_funs(s, u, p, U.data(), N);
      for (int j = 0; j <= p; ++j) out[s - p + j] = N[j];
    };
    for (int k = 1; k < 50; ++k) {
      const double u = k / 50.0 + 0.0031;
      const int s = find_span(n - 1, p, u, U.data());
      const double h = 1e-6;
      if (U[s] > u - 2 * h || U[s + 1] < u + 2 * h) continue;  // stay inside one span
      double ders[3][kMaxOrder];
      ders_basis_funs(s, u, p, 2, U.data(), ders);
      std::vector<double> a, b, c;
      full(u - h, a);
      full(u, b);
      full(u + h, c);
      for (int j = 0; j <= p; ++j) {
        const int i = s - p + j;
        EXPECT_NEAR(ders[1][j], (c[i] - a[i]) / (2 * h), 1e-5 * (1 + std::abs(ders[1][j])));
        EXPECT_NEAR(ders[2][j], (c[i] - 2 * b[i] + a[i]) / (h * h),
                    1e-2 * (1 + std::abs(ders[2][j])));
      }
    }
  }
}

TEST(NurbsCurve, DerivativesMatchFiniteDifferences) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto c = test::random_curve<3>(seed, 1 + seed % 4, 9);
    for (int k = 1; k < 40; ++k) {
      const double t = k / 40.0 + 0.0017, h = 1e-6;
      const auto d = c.eval(t), dm = c.eval(t - h), dp = c.eval(t + h);
      EXPECT_LT((d.c - c.point(t)).norm(), 1e-13);
      const Vec3d fd1 = (dp.c - dm.c) / (2 * h), fd2 = (dp.d1 - dm.d1) / (2 * h);
      if ((dp.d2 - dm.d2).norm() > 1e3) continue;  // a knot between t-h and t+h
      EXPECT_LT((fd1 - d.d1).norm(), 1e-6 * (1 + d.d1.norm())) << seed << " " << t;
      EXPECT_LT((fd2 - d.d2).norm(), 1e-5 * (1 + d.d2.norm())) << seed << " " << t;
    }
  }
}

TEST(NurbsSurface, DerivativesMatchFiniteDifferences) {
  const auto s = test::random_surface(3, 3, 2, 6, 5);
  for (int k = 1; k < 12; ++k)
    for (int l = 1; l < 12; ++l) {
      const double u = k / 12.0 + 0.003, v = l / 12.0 + 0.002, h = 1e-6;
      const auto d = s.eval(u, v);
      const auto du0 = s.eval(u - h, v), du1 = s.eval(u + h, v);
      const auto dv0 = s.eval(u, v - h), dv1 = s.eval(u, v + h);
      EXPECT_LT((d.s - s.point(u, v)).norm(), 1e-13);
      EXPECT_LT(((du1.s - du0.s) / (2 * h) - d.su).norm(), 1e-5 * (1 + d.su.norm()));
      EXPECT_LT(((dv1.s - dv0.s) / (2 * h) - d.sv).norm(), 1e-5 * (1 + d.sv.norm()));
      if ((du1.suu - du0.suu).norm() > 1e3 || (dv1.svv - dv0.svv).norm() > 1e3) continue;
      EXPECT_LT(((du1.su - du0.su) / (2 * h) - d.suu).norm(), 1e-4 * (1 + d.suu.norm()));
      EXPECT_LT(((dv1.sv - dv0.sv) / (2 * h) - d.svv).norm(), 1e-4 * (1 + d.svv.norm()));
      EXPECT_LT(((dv1.su - dv0.su) / (2 * h) - d.suv).norm(), 1e-4 * (1 + d.suv.norm()));
    }
}
