#include "curvsph/analysis/oscillating_force.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace curvsph {
namespace {

constexpr double kPi = std::numbers::pi;

// Least squares M c = y over the rows that `row` fills for the samples in [t0, t1]; the
// columns are the regressors of one sample. Normal equations would square the conditioning;
// a column-pivoted QR does not.
template <int N, class Row>
Eigen::Matrix<double, N, 1> least_squares(const std::vector<double>& t,
                                          const std::vector<double>& f, double t0, double t1,
                                          Row row) {
  if (t.size() != f.size())
    throw std::invalid_argument("oscillating_force: time and force samples differ in number");
  std::vector<std::size_t> in;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0 && t[k] <= t1) in.push_back(k);
  if (in.size() < static_cast<std::size_t>(N))
    throw std::invalid_argument("oscillating_force: " + std::to_string(in.size()) +
                                " samples in the fitting window, " + std::to_string(N) + " needed");
  Eigen::MatrixXd M(static_cast<Eigen::Index>(in.size()), N);
  Eigen::VectorXd y(static_cast<Eigen::Index>(in.size()));
  for (std::size_t r = 0; r < in.size(); ++r) {
    const auto i = static_cast<Eigen::Index>(r);
    const Eigen::Matrix<double, N, 1> x = row(t[in[r]]);
    M.row(i) = x.transpose();
    y(i) = f[in[r]];
  }
  return M.colPivHouseholderQr().solve(y);
}

}  // namespace

double InlineOscillation::omega() const {
  return 2 * kPi * frequency;
}
double InlineOscillation::velocity(double t) const {
  return -u_max * std::cos(omega() * t);
}
double InlineOscillation::acceleration(double t) const {
  return u_max * omega() * std::sin(omega() * t);
}
double InlineOscillation::force_scale() const {
  return rho * u_max * u_max * diameter;
}

double morison_force(const InlineOscillation& osc, const MorisonCoefficients& c, double t) {
  const double u = osc.velocity(t), D = osc.diameter;
  return -0.5 * osc.rho * D * c.cd * std::abs(u) * u -
         osc.rho * kPi * D * D / 4 * c.ci * osc.acceleration(t);
}

double FirstHarmonic::amplitude() const {
  return std::hypot(a, b);
}
double FirstHarmonic::phase() const {
  return std::atan2(b, a);
}

FirstHarmonic fit_first_harmonic(const std::vector<double>& t, const std::vector<double>& f,
                                 double omega, double t0, double t1) {
  const Eigen::Vector3d c = least_squares<3>(t, f, t0, t1, [&](double s) {
    return Eigen::Vector3d(1.0, std::cos(omega * s), std::sin(omega * s));
  });
  return {c(0), c(1), c(2)};
}

MorisonCoefficients fit_morison(const std::vector<double>& t, const std::vector<double>& f,
                                const InlineOscillation& osc, double t0, double t1) {
  const double D = osc.diameter;
  const Eigen::Vector2d c = least_squares<2>(t, f, t0, t1, [&](double s) {
    const double u = osc.velocity(s);
    return Eigen::Vector2d(-0.5 * osc.rho * D * std::abs(u) * u,
                           -osc.rho * kPi * D * D / 4 * osc.acceleration(s));
  });
  return {c(0), c(1)};
}

FirstHarmonic morison_first_harmonic(const InlineOscillation& osc, const MorisonCoefficients& c,
                                     int n) {
  // n samples evenly over one period (the end point left out: it repeats the start), for which
  // the discrete least squares is the exact Fourier coefficient of every harmonic below n/2.
  const double T = 1 / osc.frequency;
  std::vector<double> t(static_cast<std::size_t>(n)), f(t.size());
  for (int k = 0; k < n; ++k) {
    t[static_cast<std::size_t>(k)] = T * k / n;
    f[static_cast<std::size_t>(k)] = morison_force(osc, c, t[static_cast<std::size_t>(k)]);
  }
  return fit_first_harmonic(t, f, osc.omega(), 0, T);
}

double phase_difference(double a, double b) {
  double d = std::remainder(a - b, 2 * kPi);  // in [-pi, pi]
  if (d <= -kPi) d += 2 * kPi;
  return d;
}

}  // namespace curvsph
