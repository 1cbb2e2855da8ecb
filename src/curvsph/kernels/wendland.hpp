#pragma once
// Wendland C2 kernel with support radius 2h (DESIGN.md §4):
//   W(q) = alpha_d (1 - q/2)^4 (2q + 1),  q = r/h,
//   alpha_2 = 7 / (4 pi h^2),  alpha_3 = 21 / (16 pi h^3).
// Barker's "quintic Wendland", Vela Vela's "4th-order Wendland" and Calderon's s = 2
// Wendland are this kernel.
#include <numbers>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
struct WendlandC2 {
  static_assert(D == 2 || D == 3);
  Real h;
  Real inv_h;
  Real alpha;  // normalisation alpha_d
  Real support;
  Real support2;
  Real gradient_coef;  // -5 alpha / h^2 (gradient_factor)

  explicit WendlandC2(Real h_) : h(h_), inv_h(Real(1) / h_) {
    const Real pi = std::numbers::pi_v<Real>;
    alpha = D == 2 ? Real(7) / (Real(4) * pi * h * h) : Real(21) / (Real(16) * pi * h * h * h);
    support = 2 * h;
    support2 = support * support;
    gradient_coef = -5 * alpha * inv_h * inv_h;
  }

  // W(r); zero for r >= 2h.
  Real value(Real r) const {
    if (r >= support) return 0;  // exact: r * inv_h can round to just below 2 at r = 2h
    const Real q = r * inv_h;
    const Real t = 1 - Real(0.5) * q;
    const Real t2 = t * t;
    return alpha * t2 * t2 * (2 * q + 1);
  }

  // dW/dr; dW/dq = -5 q (1 - q/2)^3, so dW/dr = -5 alpha q (1 - q/2)^3 / h.
  Real derivative(Real r) const {
    if (r >= support) return 0;
    const Real q = r * inv_h;
    const Real t = 1 - Real(0.5) * q;
    return -5 * alpha * q * t * t * t * inv_h;
  }

  // (1/r) dW/dr, finite at r = 0: grad W = x_ij * this.
  Real gradient_factor(Real r) const {
    if (r >= support) return 0;
    const Real q = r * inv_h;
    const Real t = 1 - Real(0.5) * q;
    return (gradient_coef * t) * (t * t);  // two multiplications deep, not five
  }

  Real value_at_zero() const { return alpha; }
};

}  // namespace curvsph
