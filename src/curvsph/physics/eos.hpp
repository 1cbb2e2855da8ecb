#pragma once
// Equations of state with a background pressure p0 (DESIGN.md §4):
//   Tait:   p = c0^2 rho0 / gamma ((rho/rho0)^gamma - 1) + p0
//   linear: p = c0^2 (rho - rho0) + p0
#include <cmath>

#include "curvsph/core/types.hpp"

namespace curvsph {

struct Eos {
  enum class Type { tait, linear } type = Type::tait;
  Real c0 = 1;
  Real gamma = 7;
  Real p0 = 0;

  Real pressure(Real rho, Real rho0) const {
    if (type == Type::linear) return c0 * c0 * (rho - rho0) + p0;
    return c0 * c0 * rho0 / gamma * (std::pow(rho / rho0, gamma) - 1) + p0;
  }
  // Inverse: the density that gives pressure p (initial pressure fields).
  Real density(Real p, Real rho0) const {
    if (type == Type::linear) return rho0 + (p - p0) / (c0 * c0);
    return rho0 * std::pow(1 + gamma * (p - p0) / (c0 * c0 * rho0), 1 / gamma);
  }
  // Local speed of sound sqrt(dp/drho).
  Real sound_speed(Real rho, Real rho0) const {
    if (type == Type::linear) return c0;
    return c0 * std::pow(rho / rho0, (gamma - 1) / 2);
  }
};

}  // namespace curvsph
