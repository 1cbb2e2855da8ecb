// Water at rest over a step and a ramp: a 2-D tank whose wall is one polygon (a degree-1 NURBS
// curve) with a floor 2 m long that rises by 0.2 m at x = 1 m, vertically (a convex corner of
// 270 degrees at the top of the step) or at 60 degrees (240 degrees at the top of the ramp).
// Reference: the hydrostatic field rho0 g (H - y) of the run's own analysis, H = 0.5 m. Coarse
// (H/dx = 10, 1 s, packed, mirror ghosts, one thread); the H/dx = 20 figures at 200 to 300
// degrees are in docs/geometry.md ("Ghosts at sharp corners and edges").
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <iostream>

#include "../support/quiet_run.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {
namespace {

// theta: the fluid's angle at the top corner, 180 to 270 degrees.
YAML::Node step_tank(int theta_deg) {
  const double rise = 0.2, slope = (theta_deg - 180) * M_PI / 180.0;
  const double top = theta_deg == 270 ? 1.0 : 1.0 + rise / std::tan(slope);
  return YAML::Load(fmt::format(
      "{{name: step_tank, dimension: 2, resolution: {{dx: 0.05, h_over_dx: 2}}, "
      "fluids: [{{name: water, rho0: 1000, viscosity: 1.0e-3, "
      "region: {{box: {{min: [-0.1, 0], max: [2.1, 0.5]}}}}}}], "
      "initial: {{hydrostatic: {{depth: 0.5}}}}, eos: {{type: linear, c0: 22.1, p0: 0}}, "
      "density: {{method: continuity, delta_sph: 0.1}}, gravity: [0, -9.81], "
      "walls: [{{shape: nurbs_curve, degree: 1, fluid: left, knots: [0, 0, 1, 2, 3, 4, 5, 5], "
      "control_points: [[0, 0.7], [0, 0], [1, 0], [{:.12g}, {}], [2, {}], [2, 0.7]]}}], "
      "boundary: {{method: ghost, map: mirror}}, setup: {{relax: {{free_faces: hold}}}}, "
      "time: {{end: 1.0, cfl: 0.25}}, output: {{every: 0.1, vtk: false}}, "
      "analysis: {{hydrostatic: {{depth: 0.5}}}}}}",
      top, rise, rise));
}

class ConvexTank : public ::testing::TestWithParam<int> {};

TEST_P(ConvexTank, StaysAtRest) {
  // The solid's wedge at the top corner filled once by the faces' images, each weighted by its
  // share (facet_images.hpp). Measured: 0.0120 (270) and 0.0116 (240 degrees) deep, no wall
  // contact; with the images of before (each face's while the particle projects onto it, the
  // point image beyond both: the solid covered up to three times) 0.0338 with 1121 wall
  // contacts by 2 particles (270) and 0.0122 (240). Bound: the 2 %.
  const int theta = GetParam();
  const auto m = test::run_quiet(read_case(step_tank(theta), "step_tank.yaml"), 1);
  EXPECT_NEAR(m["time_reached"].get<double>(), 1.0, 1e-9);
  EXPECT_EQ(m["particles_projected"].get<long>(), 0);
  EXPECT_EQ(m["escaped_particles"].get<long>(), 0);
  EXPECT_EQ(m["particles_removed"].get<long>(), 0);
  EXPECT_EQ(m["wall_contacts"].get<long>(), 0);
  std::cout << fmt::format("step tank {}: p_deep {:.4f} contacts {} ke {:.2e}\n", theta,
                           m["pressure_l2_error_deep"].get<double>(),
                           m["wall_contacts"].get<long>(), m["kinetic_energy_max"].get<double>());
  EXPECT_LT(m["pressure_l2_error_deep"].get<double>(), 0.02) << theta;
}

INSTANTIATE_TEST_SUITE_P(Angles, ConvexTank, ::testing::Values(240, 270));

}  // namespace
}  // namespace curvsph
