#pragma once
// Steady analytic profiles of the two wall-bounded validation flows (issue #4):
//  - circular Couette flow between concentric cylinders R_i < R_o turning at omega_i, omega_o
//    (Barker eq. 24, Wendl 1999): v_theta(r) = A r + B / r with
//      A = (omega_o R_o^2 - omega_i R_i^2) / (R_o^2 - R_i^2),
//      B = (omega_i - omega_o) R_i^2 R_o^2 / (R_o^2 - R_i^2),
//    and the radial balance dp/dr = rho v_theta^2 / r;
//  - plane Poiseuille (and Couette–Poiseuille) flow between two parallel walls a distance H
//    apart, driven by a constant acceleration g along the walls and, optionally, Vela Vela's
//    drive term (v0 - u)/tau:  nu u'' + g + (v0 - u)/tau = 0, u(0) = u0, u(H) = u1.
//    Without the drive u(y) = u0 + (u1 - u0) y/H + g/(2 nu) y (H - y).
#include <algorithm>
#include <cmath>

namespace curvsph {

struct CouetteFlow {
  double r_in = 0.025, r_out = 0.040;
  double omega_in = 1.0, omega_out = 0.0;

  double A() const {
    return (omega_out * r_out * r_out - omega_in * r_in * r_in) / (r_out * r_out - r_in * r_in);
  }
  double B() const {
    return (omega_in - omega_out) * r_in * r_in * r_out * r_out / (r_out * r_out - r_in * r_in);
  }
  double v_theta(double r) const { return A() * r + B() / r; }
  // p(r) - p(r_in) for density rho: integral of rho v^2 / r from r_in to r.
  double pressure(double r, double rho) const {
    auto F = [&](double s) {
      const double a = A(), b = B();
      return a * a * s * s / 2 + 2 * a * b * std::log(s) - b * b / (2 * s * s);
    };
    return rho * (F(r) - F(r_in));
  }
  // Largest wall speed: the velocity scale of the relative error.
  double speed_scale() const {
    return std::max(std::abs(omega_in) * r_in, std::abs(omega_out) * r_out);
  }
};

struct ChannelFlow {
  double H = 1.0;   // wall distance
  double nu = 1.0;  // kinematic viscosity
  double g = 0.0;   // constant acceleration along the walls
  double u0 = 0.0;  // wall speeds along the flow direction (y = 0 and y = H)
  double u1 = 0.0;
  bool drive = false;  // Vela Vela eq. 36 term (v0 - u)/tau
  double v0 = 0.0, tau = 1.0;

  // Velocity along the walls at distance y from the first wall.
  double velocity(double y) const {
    if (!drive) return u0 + (u1 - u0) * y / H + g / (2 * nu) * y * (H - y);
    // nu u'' - u/tau = -(g + v0/tau): u = U + a cosh(y/l) + b sinh(y/l), U = g tau + v0.
    const double l = std::sqrt(nu * tau), U = g * tau + v0;
    const double a = u0 - U;
    const double b = (u1 - U - a * std::cosh(H / l)) / std::sinh(H / l);
    return U + a * std::cosh(y / l) + b * std::sinh(y / l);
  }
};

}  // namespace curvsph
