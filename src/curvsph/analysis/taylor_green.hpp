#pragma once
// The 2-D Taylor–Green vortex on the periodic square [0, L]^2 (issue #2 validation case):
//   u =  U sin(kx) cos(ky) e^{-2 nu k^2 t},  v = -U cos(kx) sin(ky) e^{-2 nu k^2 t},
//   p =  rho U^2 / 4 (cos 2kx + cos 2ky) e^{-4 nu k^2 t},  k = 2 pi / L,
// so the kinetic energy decays at the rate 4 nu k^2 (= 16 pi^2 nu for L = 1).
#include <cmath>
#include <numbers>

#include "curvsph/core/types.hpp"

namespace curvsph {

struct TaylorGreen {
  double U = 1, L = 1, nu = 0.01, rho = 1;
  double origin_x = 0, origin_y = 0;

  double k() const { return 2 * std::numbers::pi / L; }
  double energy_decay_rate() const { return 4 * nu * k() * k(); }
  Vec2d velocity(double x, double y, double t) const {
    const double kx = k() * (x - origin_x), ky = k() * (y - origin_y);
    const double f = U * std::exp(-2 * nu * k() * k() * t);
    return {f * std::sin(kx) * std::cos(ky), -f * std::cos(kx) * std::sin(ky)};
  }
  double pressure(double x, double y, double t) const {
    const double kx = k() * (x - origin_x), ky = k() * (y - origin_y);
    return rho * U * U / 4 * (std::cos(2 * kx) + std::cos(2 * ky)) *
           std::exp(-4 * nu * k() * k() * t);
  }
};

}  // namespace curvsph
