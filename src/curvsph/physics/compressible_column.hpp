#pragma once
// Gauge pressure p(z) at depth z of a weakly compressible liquid at rest: dp/dz = rho(p) g,
// p(0) = 0 (hydrostatic balance with the EOS density, not with rho0). With rho = rho0 +
// p/c0^2 (linear EOS) this is p = rho0 c0^2 (exp(g z/c0^2) - 1), above rho0 g z by a relative
// g z/(2 c0^2) (0.5 % at the bottom of the tank at c0 = 10 sqrt(g H)): the SPH momentum
// equation sees that difference as an unbalanced force of 1 % of g and rings the column.
// Classical RK4 on a fine table (any EOS), linear interpolation in between. Used by
// `initial.hydrostatic` (analysis/hydrostatic_analysis.cpp) and the default hydrostatic start
// (setup/hydrostatic_start.cpp).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "curvsph/physics/eos.hpp"

namespace curvsph {

class CompressibleColumn {
 public:
  CompressibleColumn(const Eos& eos, Real rho0, double g, double depth)
      : dz_(depth / kSteps), p_(kSteps + 1, 0.0) {
    auto rate = [&](double p) {
      return static_cast<double>(eos.density(static_cast<Real>(p + eos.p0), rho0)) * g;
    };
    for (int k = 0; k < kSteps; ++k) {
      const double p = p_[k];
      const double k1 = rate(p), k2 = rate(p + 0.5 * dz_ * k1), k3 = rate(p + 0.5 * dz_ * k2),
                   k4 = rate(p + dz_ * k3);
      p_[k + 1] = p + dz_ / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
  }
  // Gauge pressure at depth z (0 above the surface; linear continuation below the bottom).
  double operator()(double z) const {
    if (z <= 0 || dz_ <= 0) return 0;
    const auto k = std::min(static_cast<std::size_t>(z / dz_), std::size_t{kSteps - 1});
    const double f = z / dz_ - static_cast<double>(k);  // > 1 below the bottom
    return p_[k] + f * (p_[k + 1] - p_[k]);
  }

 private:
  static constexpr int kSteps = 20000;
  double dz_;
  std::vector<double> p_;
};

}  // namespace curvsph
