#pragma once
// The small boundary-integral tank of the BI tests: a 0.1 m wide box tank with water at rest
// 0.048 m deep (25 x 12 = 300 particles at dx = 4 mm, h = 2 dx), c0 = 10 sqrt(g H), continuity
// density with delta-SPH, the given Shepard mode.
#include <yaml-cpp/yaml.h>

#include <string>

namespace curvsph::test {

inline YAML::Node bi_tank(const std::string& shepard) {
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.004, h_over_dx: 2}
fluids: [{rho0: 998, viscosity: 8.94e-4, region: {box: {min: [0, 0], max: [0.1, 0.048]}}}]
initial: {hydrostatic: {depth: 0.048}}
eos: {type: linear, c0: 6.9, p0: 0}
density: {method: continuity, delta_sph: 0.1}
gravity: [0, -9.81]
walls: [{shape: box, min: [0, 0], max: [0.1, 0.08], fluid: inside}]
time: {end: 1.0, cfl: 0.25, max_steps: 300}
analysis: {hydrostatic: {depth: 0.048}}
)");
  root["boundary"] = YAML::Load("{method: integrals, shepard: " + shepard + "}");
  return root;
}

}  // namespace curvsph::test
