#pragma once
// Boundary kernel F of the geometric Shepard factor (Calderon et al., DESIGN.md §4):
//   rho^(1-d) d(rho^d F)/d rho = W(rho),  F(2h) = 0,  F = 0 beyond the support,
// for the Wendland C2 kernel (support 2h). With q = r/h (corrected forms, verified
// symbolically: the paper's eqs. 11-12 have the polynomial's sign and the 3-D constant wrong):
//   2-D: h^2 F(q) = [q^5/32 - 35q^4/128 + 7q^3/8 - 35q^2/32 + 7/8]/pi - 1/(2 pi q^2)
//   3-D: h^3 F(q) = [21q^5/1024 - 45q^4/256 + 35q^3/64 - 21q^2/32 + 7/16]/pi - 1/(4 pi q^3)
// Equivalently F = (m(r) - 1)/(S_d r^d) with m(r) the kernel mass within radius r and
// S_d = 2 pi (2-D), 4 pi (3-D); F_P = m/(S_d r^d) (a polynomial), F_D = -1/(S_d r^d).
//
// Split used by the geometric Shepard factor: F = F_D + F_Pext for every r > 0, where
// F_Pext = F_P inside the support and F_Pext = -F_D outside (so that F = 0 there). F_Pext is
// C^4 across r = 2h, so it integrates accurately with Gauss points even over elements that
// cross the support sphere, while F_D integrates exactly to the subtended angle over whole
// elements. Elements entirely beyond 2h contribute nothing (F_D + F_Pext = 0 there).
#include <numbers>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
struct BoundaryKernel {
  static_assert(D == 2 || D == 3);
  double h;
  double inv_h;
  double inv_hd;  // 1 / h^d

  explicit BoundaryKernel(double h_)
      : h(h_), inv_h(1.0 / h_), inv_hd(D == 2 ? 1.0 / (h_ * h_) : 1.0 / (h_ * h_ * h_)) {}

  // Dimensionless parts, q = r/h.
  static double polynomial_q(double q) {
    constexpr double pi = std::numbers::pi;
    if constexpr (D == 2) {
      return ((((q / 32.0 - 35.0 / 128.0) * q + 7.0 / 8.0) * q - 35.0 / 32.0) * q * q + 7.0 / 8.0) /
             pi;
    } else {
      return ((((21.0 / 1024.0 * q - 45.0 / 256.0) * q + 35.0 / 64.0) * q - 21.0 / 32.0) * q * q +
              7.0 / 16.0) /
             pi;
    }
  }
  static double singular_q(double q) {
    constexpr double pi = std::numbers::pi;
    if constexpr (D == 2) {
      return -1.0 / (2.0 * pi * q * q);
    } else {
      return -1.0 / (4.0 * pi * q * q * q);
    }
  }

  // F_P(r): the polynomial part (meaningful for r < 2h).
  double polynomial(double r) const { return polynomial_q(r * inv_h) * inv_hd; }
  // F_D(r) = -1/(2 pi r^2) (2-D), -1/(4 pi r^3) (3-D), for every r > 0.
  double singular(double r) const { return singular_q(r * inv_h) * inv_hd; }
  // F(r): F_P + F_D inside the support, 0 for r >= 2h.
  double value(double r) const {
    const double q = r * inv_h;
    return q >= 2.0 ? 0.0 : (polynomial_q(q) + singular_q(q)) * inv_hd;
  }
  // F - F_D for every r > 0: F_P inside the support, -F_D outside.
  double polynomial_extended(double r) const {
    const double q = r * inv_h;
    return (q >= 2.0 ? -singular_q(q) : polynomial_q(q)) * inv_hd;
  }
  double support() const { return 2.0 * h; }
};

}  // namespace curvsph
