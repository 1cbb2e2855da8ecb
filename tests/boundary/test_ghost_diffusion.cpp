// The ghosts' share of the delta-SPH diffusive term keeps water at rest under gravity at rest
// (boundary/ghost/ghost_boundary.cpp, add_density_rate). Reference: the hydrostatic state of
// the linear EOS, rho^H(y) with d rho / dy = -rho g / c0^2, is steady, so the exact density
// rate is 0. The ghost of a hydrostatic ghost pressure continues the source's pressure along
// the hydrostatic gradient; its density, taken as the source's alone (the Molteni difference
// rho_s - rho_i), diffused the profile into the wall: a rate of order delta rho g / c0 at every
// particle near a wall, which made a 60 degree V trough at H/dx = 8 lose 0.14 rho g H of
// pressure along its bottom edge in 1 s (docs/validation/cad_at_rest/findings.md). Water in a
// corner of two plane walls at rest, one evaluation of the rates at the hydrostatic start.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>

#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

constexpr double kH = 0.02, kL = 0.03, kG = 9.81;

Case corner(const std::string& term, const std::string& map) {
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.001, h_over_dx: 2}
domain: {min: [-0.01, -0.01], max: [0.04, 0.04]}
fluids: [{rho0: 1000, viscosity: 0, region: {box: {min: [0, 0], max: [0.03, 0.02]}}}]
initial: {hydrostatic: {depth: 0.02, bottom: 0}}
eos: {type: linear, c0: 4.43, p0: 0}
gravity: [0, -9.81]
walls:
  - {shape: plane, point: [0, 0], normal: [0, 1]}
  - {shape: plane, point: [0, 0], normal: [1, 0]}
time: {end: 1.0e-9, dt_max: 1.0e-9}
output: {vtk: false}
)");
  root["density"] =
      YAML::Load("{method: continuity, delta_sph: 0.1, diffusion_term: " + term + "}");
  root["boundary"] = YAML::Load("{method: ghost, ghost_pressure: hydrostatic, map: " + map + "}");
  return read_case(root, "ghost_diffusion_test");
}

// Largest |drho/dt| over the particles within 2h of a wall whose support the free surface and
// the open far side do not cut, over delta rho0 g / c0 (the Molteni difference's scale).
double wall_rate(const std::string& term, const std::string& map, int& counted) {
  const Case c = corner(term, map);
  Solver<2> s(c);
  s.initialize();
  s.step();
  const auto& P = s.particles();
  const double support = 2 * c.h(), scale = 0.1 * 1000 * kG / 4.43;
  double worst = 0;
  counted = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double x = P.x[i].x(), y = P.x[i].y();
    if (!(x < support || y < support) || x > kL - support || y > kH - support) continue;
    ++counted;
    worst = std::max(worst, std::abs(static_cast<double>(P.drho[i])) / scale);
  }
  return worst;
}

TEST(GhostDiffusion, HydrostaticStateIsSteadyNextToWalls) {
  for (const char* term : {"antuono", "fourtakas"})
    for (const char* map : {"mirror", "mirror_beta"}) {
      int n = 0;
      const double rate = wall_rate(term, map, n);
      std::cout << term << " " << map << ": " << n << " particles, max |drho/dt| = " << rate
                << " delta rho0 g / c0\n";
      EXPECT_GT(n, 100);
      EXPECT_LT(rate, 1e-3) << term << " " << map;
    }
}

}  // namespace
}  // namespace curvsph
