// Walls that nothing crosses (boundary/wall_impact.hpp): a water column collapsing in a tank
// onto a cylinder, with the stray-particle contact off, must keep every particle on the fluid
// side of every wall by the boundary treatment alone, for both families. Reference: the exact
// closest points of the walls (a particle found past one is put back and counted in
// particles_projected, which must stay 0). Without the impact pressure and the contact layer
// this column puts particles back 193 times (ghosts) and 118 times (integrals) by t = 0.6 s.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "../support/quiet_run.hpp"
#include "curvsph/boundary/wall_impact.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {
namespace {

TEST(WallImpact, PressureIsTheAcousticImpedanceTimesTheApproachSpeedOnly) {
  // Linearised Riemann problem at a rigid wall: rho c0 u_a, compression only.
  EXPECT_DOUBLE_EQ(wall_impact_pressure(1000, 28, Real(0.25), Real(0), kImpactReachIntegrals),
                   7000);
  EXPECT_DOUBLE_EQ(wall_impact_pressure(1000, 28, Real(-0.25), Real(0), kImpactReachIntegrals), 0);
}

// 200 particles (dx = 0.02, h = 2 dx): a 0.2 x 0.4 m column released in a 0.7 x 0.5 m tank,
// its surge hitting a cylinder of radius 0.1 m on the floor (0.04 m under it) and the far wall.
YAML::Node column_on_cylinder(const std::string& method) {
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.02, h_over_dx: 2}
fluids:
  - {rho0: 1000, viscosity: 1.0e-3, region: {box: {min: [0, 0], max: [0.2, 0.4]}}}
initial: {hydrostatic: {depth: 0.4}}
gravity: [0, -9.81]
walls:
  - {shape: box, min: [0, 0], max: [0.7, 0.5], fluid: inside}
  - {shape: circle, center: [0.45, 0.14], radius: 0.1, fluid: outside}
boundary: {contact: 0}
time: {end: 0.6}
output: {vtk: false}
)");
  root["boundary"]["method"] = method;
  return root;
}

class WallImpactColumn : public ::testing::TestWithParam<std::string> {};

TEST_P(WallImpactColumn, NoParticleCrossesAWallWithoutTheContactSafeguard) {
  const auto m = test::run_quiet(read_case(column_on_cylinder(GetParam()), "column"), 1);
  EXPECT_NEAR(m["time_reached"].get<double>(), 0.6, 1e-9);
  EXPECT_EQ(m["particles_projected"].get<long>(), 0);
  EXPECT_EQ(m["wall_contacts"].get<long>(), 0);  // boundary.contact: 0
  EXPECT_EQ(m["particles_removed"].get<long>(), 0);
}

INSTANTIATE_TEST_SUITE_P(Methods, WallImpactColumn, ::testing::Values("ghost", "integrals"));

}  // namespace
}  // namespace curvsph
