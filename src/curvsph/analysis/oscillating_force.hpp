#pragma once
// The in-line force on a cylinder oscillating in fluid at rest (Dütsch, Durst, Becker &
// Lienhart 1998, J. Fluid Mech. 360, 249-271; `curvsph validate oscillating_cylinder`).
//
// Motion (the paper's convention): x(t) = x0 - A sin(omega t), so the cylinder's velocity is
// u(t) = -U cos(omega t) and its acceleration du/dt = U omega sin(omega t), with
// U = omega A, omega = 2 pi f, KC = U / (f D), Re = U D / nu.
//
// Reference force: the Morison equation with the drag and inertia coefficients that Dütsch
// et al. give for Re = 100, KC = 5, C_d = 2.09 and C_i = 1.45 (the values later papers quote;
// data/dutsch1998/README.md: the paper's text was not at hand, but its force curve as
// digitised by cuIBM's validation data has a first harmonic within 2.2 % in amplitude and 3
// degrees in phase of this formula's),
//   F(t) = -1/2 rho D C_d |u| u - rho (pi D^2 / 4) C_i du/dt                         (Morison)
// per unit depth, both terms opposing the cylinder's motion. Written with the fluid's velocity
// relative to the cylinder, u_rel = -u, it is the usual F = 1/2 rho D C_d u_rel |u_rel| +
// rho (pi D^2/4) C_i du_rel/dt.
//
// Comparison: least squares over whole periods, of
//   (a) the first harmonic F ~ a0 + a cos(omega t) + b sin(omega t): amplitude sqrt(a^2 + b^2)
//       and phase atan2(b, a) (F = amplitude cos(omega t - phase)), both measured on the same
//       time origin as the motion above;
//   (b) the Morison form itself: C_d and C_i.
#include <vector>

namespace curvsph {

struct InlineOscillation {
  double diameter = 0;   // D
  double rho = 0;        // fluid density
  double u_max = 0;      // U = omega A
  double frequency = 0;  // f

  double omega() const;
  double velocity(double t) const;      // u(t) = -U cos(omega t)
  double acceleration(double t) const;  // du/dt = U omega sin(omega t)
  double force_scale() const;           // rho U^2 D: the paper's unit of the in-line force
};

struct MorisonCoefficients {
  double cd = 0;  // drag coefficient C_d
  double ci = 0;  // inertia coefficient C_i
};

// Eq. (Morison) above at time t.
double morison_force(const InlineOscillation& osc, const MorisonCoefficients& c, double t);

// F(t) ~ mean + a cos(omega t) + b sin(omega t).
struct FirstHarmonic {
  double mean = 0, a = 0, b = 0;
  double amplitude() const;
  double phase() const;  // radians, in (-pi, pi]
};

// Least-squares fit over the samples with t in [t0, t1] (t and f of the same length; at least
// three samples there, else throws std::invalid_argument).
FirstHarmonic fit_first_harmonic(const std::vector<double>& t, const std::vector<double>& f,
                                 double omega, double t0, double t1);

// Least-squares fit of C_d, C_i of eq. (Morison) over the samples with t in [t0, t1].
MorisonCoefficients fit_morison(const std::vector<double>& t, const std::vector<double>& f,
                                const InlineOscillation& osc, double t0, double t1);

// The first harmonic of eq. (Morison) itself (a fit over n samples of one period).
FirstHarmonic morison_first_harmonic(const InlineOscillation& osc, const MorisonCoefficients& c,
                                     int n = 2000);

// a - b wrapped to (-pi, pi].
double phase_difference(double a, double b);

}  // namespace curvsph
