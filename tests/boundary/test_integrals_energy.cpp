// Energy budget of the boundary integrals: a closed periodic channel (floor and lid, no free
// surface, no corner) held at rest under gravity, without any dissipation (delta-SPH 0,
// viscosity 0). The total energy
//   E = sum_i m_i (|u_i|^2 / 2 - g.x_i + e(rho_i)),  e = c0^2 (ln(rho/rho0) + rho0/rho - 1)
// (the internal energy of the linear EOS p = c0^2 (rho - rho0): de/drho = p/rho^2) is a
// constant of the semi-discrete equations when the wall and fluid terms are energy-consistent
// pairs (integrals_boundary.cpp, item 9); mirror ghosts are the reference that the measure
// itself is sound.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

constexpr double kH = 0.08, kRho0 = 1000, kG = 9.81;
constexpr double kDriftBound = 2e-4;  // of M g H

// Channel of depth H = 0.08 at H/dx = 6 (h = 2 dx: every particle is within 2h of a wall),
// 0.16 long, periodic in x; c0 = 10 sqrt(g H).
YAML::Node channel(const std::string& boundary) {
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.0133333333333, h_over_dx: 2}
domain: {min: [0, 0], max: [0.16, 0.08], periodic: [true, false]}
fluids: [{rho0: 1000, viscosity: 0, region: {box: {min: [0, 0], max: [0.16, 0.08]}}}]
initial: {hydrostatic: {depth: 0.08}}
eos: {type: linear, c0: 8.86, p0: 0}
density: {method: continuity, delta_sph: 0}
gravity: [0, -9.81]
walls: [{shape: plane, point: [0, 0], normal: [0, 1]}, {shape: plane, point: [0, 0.08], normal: [0, -1]}]
time: {end: 10, cfl: 0.25}
)");
  root["boundary"] = YAML::Load(boundary);
  return root;
}

double energy(const Particles<2>& P, double c0) {
  double e = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double rho = P.rho[i], q = kRho0 / rho;
    e += P.mass[i] * (0.5 * P.v[i].cast<double>().squaredNorm() + kG * P.x[i][1] +
                      c0 * c0 * (std::log(rho / kRho0) + q - 1));
  }
  return e;
}

// Largest |E - E0| / (M g H) over `steps` steps.
double drift(const std::string& boundary, int steps) {
  const Case c = read_case(channel(boundary), "integrals_energy_test");
  Solver<2> s(c);
  s.initialize();
  const auto& P = s.particles();
  double M = 0;
  for (std::size_t i = 0; i < P.size(); ++i) M += P.mass[i];
  const double c0 = 8.86, e0 = energy(P, c0);
  double worst = 0;
  for (int k = 0; k < steps; ++k) {
    s.step();
    worst = std::max(worst, std::abs(energy(P, c0) - e0) / (M * kG * kH));
  }
  return worst;
}

// The measure: mirror ghosts hold |E - E0| below 1.7e-5 M g H over 0.3 s (400 steps).
TEST(IntegralsEnergy, MirrorGhostsKeepTheEnergy) {
  EXPECT_LT(drift("{method: ghost}", 200), 1e-4);
}

// Measured over these 200 steps (0.15 s), largest |E - E0| / (M g H): symmetric (the wall
// pressure p_b of the neighbours working on moving particles) 1.3e-3, conservative (the
// default) 5.6e-6, below the mirror ghosts' level; conservative_wall 7.0e-5,
// conservative_pairs 5.1e-3 (DISABLED_Forms prints them). Before the impact pressure of
// integrals_boundary.cpp item 10 (dissipative: it acts on approach only): 2.5e-3 (8.2e-2 over
// 400 steps), 1.7e-5, 2.0e-4 and 8.8e-3.
TEST(IntegralsEnergy, ConservativeWallTermsKeepTheEnergy) {
  EXPECT_LT(drift("{method: integrals, pressure: conservative}", 200), kDriftBound);
}

TEST(IntegralsEnergy, SymmetricWallTermsGainEnergy) {
  // The old form fails the bound above: this is what the conservative form fixes.
  EXPECT_GT(drift("{method: integrals, pressure: symmetric}", 200), kDriftBound);
}

TEST(IntegralsEnergy, DISABLED_Forms) {
  for (const char* f : {"symmetric", "conservative_wall", "conservative_pairs", "conservative"}) {
    const double d = drift(std::string("{method: integrals, pressure: ") + f + "}", 200);
    std::printf("form %s: max |E - E0| / MgH = %.3e\n", f, d);
  }
}

}  // namespace
}  // namespace curvsph
