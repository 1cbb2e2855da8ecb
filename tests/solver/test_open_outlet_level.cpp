// The outflow buffer stands at the fluid's own density level (solver/open_boundaries.hpp):
// a channel at rest closed by walls on three sides and an outflow on the fourth must stay at
// rest. With the buffer at rho0 (the equation-of-state density of p0) the density sum of the
// lattice, 1.0105 rho0 at h = 1.3 dx, stood above it and drained the channel at about
// 0.0105 c0 (0.15 m/s at c0 = 15 after 0.02 s). Reference: the lattice sum of the Wendland
// C2 kernel, summed here by brute force from its closed form (Wendland 1995; 2-D
// normalisation 7 / (4 pi h^2)).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <numbers>

#include "../support/quiet_run.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

// sum_j W(|x_j|) dx^2 over the square lattice x_j = dx (a, b), h = 1.3 dx.
double lattice_kernel_sum() {
  const double h = 1.3;  // in units of dx
  double s = 0;
  for (int a = -3; a <= 3; ++a)
    for (int b = -3; b <= 3; ++b) {
      const double q = std::hypot(a, b) / h;
      if (q < 2) s += 7 / (4 * std::numbers::pi * h * h) * std::pow(1 - q / 2, 4) * (2 * q + 1);
    }
  return s;
}

TEST(OpenOutletLevel, AChannelAtRestBehindAnOutflowStaysAtRest) {
  // c0 = 15, p0 = 0.05 rho0 c0^2: the sound speed and background pressure of the
  // Schäfer-Turek 2D-2 case (cases/cylinder_channel_re100.yaml).
  const YAML::Node root = YAML::Load(R"(
name: outlet_at_rest
dimension: 2
resolution: {dx: 0.01, h_over_dx: 1.3}
domain: {min: [0, 0], max: [0.35, 0.1]}
fluids: [{name: f, rho0: 1, viscosity: 1.0e-3,
          region: {box: {min: [0, 0], max: [0.3, 0.1]}}}]
eos: {type: tait, c0: 15, gamma: 7, p0: 11.25}
density: {method: summation}
walls: [{shape: plane, point: [0, 0], normal: [0, 1]},
        {shape: plane, point: [0, 0.1], normal: [0, -1]},
        {shape: plane, point: [0, 0], normal: [1, 0]}]
boundary: {method: ghost, map: mirror, velocity: no_slip}
open_boundaries:
  - {name: outlet, kind: outflow, point: [0.3, 0], normal: [-1, 0]}
time: {end: 0.02}
)");
  const Case c = read_case(root, "outlet_at_rest.yaml");
  Solver<2> s(c);
  s.initialize();
  const double kappa = lattice_kernel_sum();
  ASSERT_NEAR(kappa, 1.0105, 1e-4);  // the figure the header quotes
  EXPECT_NEAR(s.open_boundaries().density_level(), kappa, 1e-5);
  while (s.time() < 0.02) s.step();
  const auto& P = s.particles();
  double vmax = 0, rho_lo = 2, rho_hi = 0;
  long buffer = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.buffer[i] != 0) {
      ++buffer;
      EXPECT_NEAR(P.rho[i], kappa, 1e-5);  // kappa rho(p0), rho(p0) = rho0 = 1
      continue;
    }
    vmax = std::max(vmax, static_cast<double>(P.v[i].norm()));
    rho_lo = std::min(rho_lo, static_cast<double>(P.rho[i]));
    rho_hi = std::max(rho_hi, static_cast<double>(P.rho[i]));
  }
  std::printf("outlet at rest: max |v| = %.3g m/s (0.0105 c0 = %.3g), rho %.4f..%.4f\n", vmax,
              0.0105 * 15, rho_lo, rho_hi);
  EXPECT_EQ(buffer, 30);  // 10 lattice rows, 3 layers: nothing left or entered
  EXPECT_LT(vmax, 0.01);  // under a tenth of the drain 0.0105 c0 = 0.16 m/s
  EXPECT_GT(rho_lo, 1.0);
}

}  // namespace
}  // namespace curvsph
