#pragma once
// The figures of the Schäfer & Turek (1996) cylinder-in-a-channel benchmark from sampled
// histories: force coefficients, their time averages (2D-1, steady, Re = 20) and the
// periodic figures of vortex shedding (2D-2, Re = 100): Strouhal number, C_D,max, C_L,max and
// the pressure difference half a period after the lift maximum. Pure functions of the
// samples, so that they can be checked against synthetic signals with known answers
// (tests/analysis/test_cylinder_benchmark.cpp); the study that runs the cases is
// validation/cylinder_benchmark_study.cpp.
//
// Definitions (Schäfer & Turek 1996, §2 "Definition of the benchmark"):
//   C_D = 2 F_D / (rho U_mean^2 D),  C_L = 2 F_L / (rho U_mean^2 D),
//   U_mean = 2 U_m / 3 for the parabolic inflow of peak U_m,
//   dp = p(0.15, 0.2) - p(0.25, 0.2),  St = D f / U_mean,
//   2D-2: dp at t0 + 1/(2f), t0 the time of the lift maximum.
#include <cstddef>
#include <vector>

namespace curvsph {

// A sampled history: times (strictly increasing) and values.
struct Signal {
  std::vector<double> t, v;
};

// 2 F / (rho U^2 D): the force per unit depth over the dynamic pressure times the diameter.
double force_coefficient(double force, double rho, double u_mean, double diameter);
// The mean of the plane parabolic profile u(y) = 4 U_m y (H - y) / H^2 over [0, H]: 2 U_m / 3.
double parabolic_mean_speed(double u_max);

// Time-weighted statistics of a signal over [from, to] (trapezoidal rule over the samples in
// the window; a sampling that is denser somewhere does not weigh more there).
struct WindowStats {
  double mean = 0, std = 0, min = 0, max = 0;
  std::size_t samples = 0;
};
// Throws std::invalid_argument when fewer than two samples lie in the window.
WindowStats window_stats(const Signal& s, double from, double to);

// The signal averaged over a running window of `width` seconds centred on each sample
// (trapezoidal; the window is cut at the ends of the record). Used before taking maxima of a
// noisy signal: the maximum of the raw samples is biased upwards by the noise. A sine of
// period T loses the factor sin(pi w / T) / (pi w / T) of its amplitude (0.4 % for w = T/20).
Signal running_mean(const Signal& s, double width);

// Steady figures (2D-1): the time averages over the window, how far the record still drifts
// there (the mean over the second half of the window minus that over the first) and the
// standard error of the mean by batch means (the window cut into `batches` equal parts: the
// standard deviation of their means over sqrt(batches); Flyvbjerg & Petersen 1989, J. Chem.
// Phys. 91, 461): unlike sigma / sqrt(samples), it holds for correlated samples as long as
// a batch is longer than the noise's correlation time.
struct SteadyFigure {
  WindowStats stats;
  double drift = 0;
  double standard_error = 0;
};
SteadyFigure steady_figure(const Signal& s, double from, double to, int batches = 8);

// When a start-up transient is over: the earliest sample time after which the signal stays
// within tol |value| of `value` (NaN if its last sample is not). Applied to a running mean,
// it tells when a steady run can start averaging.
double settling_time(const Signal& s, double value, double tol);

// Periodic figures (2D-2) over [from, to], from the lift coefficient `cl`, the drag
// coefficient `cd` and the pressure difference `dp` (each its own sampling).
struct PeriodicFigures {
  bool found = false;  // at least two full periods of the lift were found
  int periods = 0;     // full periods between the first and the last upward crossing
  double frequency = 0;
  double period_spread = 0;  // the standard deviation of single periods over their mean
  double cd_max = 0, cl_max = 0, cl_min = 0;
  double dp_half_period = 0;  // mean over the periods of dp at t0 + T/2 (t0: lift maximum)
};
// Periods: the lift, averaged over a running window of `smoothing` seconds (0: the raw
// samples), crosses its window mean upwards; crossings are counted with hysteresis (the
// signal has to fall below mean - 0.5 std and rise above mean + 0.5 std between two; the
// crossing time is the linear interpolation at the last crossing of the mean before it rose
// above the band), so noise riding on the lift does not add crossings. The frequency is the
// number of full periods over the time between the first and the last crossing.
// Maxima: in each full period, each raw signal is fitted by least squares with a mean and
// three harmonics of that period; cd_max, cl_max, cl_min are the fitted curves' extrema and
// dp_half_period the fitted dp half a period after the fitted lift's maximum, averaged over
// the periods (the largest raw sample would be biased upwards by the noise).
PeriodicFigures periodic_figures(const Signal& cl, const Signal& cd, const Signal& dp, double from,
                                 double to, double smoothing);

// Linear interpolation of the signal at time t (clamped to the record's ends).
double sample_at(const Signal& s, double t);

}  // namespace curvsph
