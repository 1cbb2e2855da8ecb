#pragma once
// Composite 8-point Gauss–Legendre quadrature (exact for polynomials of degree 15 per piece):
// arc lengths, kernel shells and reference integrals share one table.
#include <array>

namespace curvsph {

inline constexpr std::array<double, 8> kGaussLegendre8Nodes = {
    -0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
    0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
inline constexpr std::array<double, 8> kGaussLegendre8Weights = {
    0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
    0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

// Integral of f over [a, b] split into `pieces` equal intervals.
template <class F>
double gauss_legendre_8(F&& f, double a, double b, int pieces = 1) {
  const double w = (b - a) / pieces;
  double sum = 0;
  for (int p = 0; p < pieces; ++p) {
    const double m = a + (p + 0.5) * w;
    for (int i = 0; i < 8; ++i)
      sum += kGaussLegendre8Weights[i] * f(m + 0.5 * w * kGaussLegendre8Nodes[i]);
  }
  return 0.5 * w * sum;
}

}  // namespace curvsph
