// Water at rest in 2-D tanks whose wall is one polygon (a degree-1 NURBS curve): the sides meet
// the floor at 60, 75, 90, 100 and 120 degrees (concave corners), every boundary method.
// Reference: the hydrostatic field rho0 g (H - y) of the run's own analysis. Coarse and short (H/dx
// = 10, 0.3 s = t sqrt(g/H) 1.3, one thread); the 1 s runs at H/dx = 20 are the study `curvsph
// validate cad_at_rest` (docs/validation/cad_at_rest).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <iostream>
#include <string>
#include <tuple>

#include "../support/quiet_run.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {
namespace {

// theta = 0: the 90 degree tank as a `box` wall instead of a polygon. The fill: the Cartesian
// lattice cut by the walls.
YAML::Node corner_tank(int theta_deg, const std::string& boundary) {
  const double H = 0.5, W = 2.0, T = 1.4 * H, dx = H / 10;
  const double c = T / std::tan(theta_deg * M_PI / 180.0);
  return YAML::Load(fmt::format(
      "{{name: corner_tank, dimension: 2, resolution: {{dx: {}, h_over_dx: 2}}, "
      "fluids: [{{name: water, rho0: 1000, viscosity: 1.0e-3, "
      "region: {{box: {{min: [{}, 0], max: [{}, {}]}}}}}}], "
      "initial: {{hydrostatic: {{depth: {}}}}}, eos: {{type: linear, c0: 22.1, p0: 0}}, "
      "density: {{method: continuity, delta_sph: 0.1}}, gravity: [0, -9.81], "
      "walls: [{{shape: nurbs_curve, degree: 1, fluid: left, knots: [0, 0, 1, 2, 3, 3], "
      "control_points: [[{:.12g}, {:.12g}], [0, 0], [{}, 0], [{:.12g}, {:.12g}]]}}], "
      "boundary: {}, time: {{end: 0.3, cfl: 0.25}}, output: {{every: 0.1, vtk: false}}, "
      "analysis: {{hydrostatic: {{depth: {}}}}}}}",
      dx, std::min(0.0, c) - 0.1, W + std::max(0.0, -c) + 0.1, H, H, c, T, W, W - c, T, boundary,
      H));
}

// The lattice packed first inside the walls and the free surface (setup.relax with
// free_faces: hold, setup/relax_closure.hpp) with the ghosts of `map`.
YAML::Node packed_tank(int theta_deg, const std::string& boundary, const std::string& map) {
  YAML::Node root = corner_tank(theta_deg, boundary);
  root["setup"] = YAML::Load("{relax: {free_faces: hold, map: " + map + "}}");
  return root;
}

YAML::Node box_tank(const std::string& boundary) {
  YAML::Node root = corner_tank(90, boundary);
  root["walls"] = YAML::Load("[{shape: box, min: [0, 0], max: [2.0, 0.7], fluid: inside}]");
  return root;
}

std::string ghost(const std::string& map) {
  return "{method: ghost, map: " + map + "}";
}

TEST(CornerTank, RightAnglePolygonIsTheBox) {
  // Reference: the box wall's own double reflections (ghosts.cpp). The polygon's corner images
  // (facet_images.hpp) are the same points with the same velocities, so the runs agree to
  // round-off. Before them the polygon gave one ghost per particle near a corner: pressure
  // error 0.149 of rho g H and 5478 wall contacts at H/dx = 20.
  const auto poly = test::run_quiet(read_case(corner_tank(90, ghost("mirror")), "tank.yaml"), 1);
  const auto box = test::run_quiet(read_case(box_tank(ghost("mirror")), "tank.yaml"), 1);
  EXPECT_EQ(poly["particles"].get<long>(), box["particles"].get<long>());
  EXPECT_NEAR(poly["pressure_l2_error"].get<double>(), box["pressure_l2_error"].get<double>(),
              1e-9);
  EXPECT_NEAR(poly["kinetic_energy_max"].get<double>(), box["kinetic_energy_max"].get<double>(),
              1e-12);
  EXPECT_EQ(poly["wall_contacts"].get<long>(), 0);
  EXPECT_LT(poly["pressure_l2_error_deep"].get<double>(), 0.02);
}

TEST(CornerTank, PackingRemovesTheLatticeError) {
  // The 60 degree tank's slanted sides cut the fill lattice at random distances; packed first
  // (setup.relax, free_faces: hold) the same particles start at the node density the ghosts
  // complete. Reference: rho g (H - y), deeper than 2h. Measured at 0.3 s: 0.240 bare,
  // 0.0075 packed (109 packing steps).
  const auto bare = test::run_quiet(read_case(corner_tank(60, ghost("mirror")), "t.yaml"), 1);
  const auto packed =
      test::run_quiet(read_case(packed_tank(60, ghost("mirror"), "mirror"), "t.yaml"), 1);
  EXPECT_EQ(bare["particles"].get<long>(), packed["particles"].get<long>());
  EXPECT_GT(bare["pressure_l2_error_deep"].get<double>(), 0.1);
  EXPECT_LT(packed["pressure_l2_error_deep"].get<double>(), 0.02);
  EXPECT_LT(packed["relax_node_density_spread"].get<double>(),
            0.1 * packed["relax_node_density_spread_initial"].get<double>());
}

class CornerTank : public ::testing::TestWithParam<std::tuple<int, std::string>> {};

TEST_P(CornerTank, StaysAtRest) {
  // Packed first with the run's ghost map (integrals: with density_preserving ghosts).
  const auto [theta, method] = GetParam();
  const bool bi = method == "integrals";
  const std::string boundary = bi ? std::string("{method: integrals}") : ghost(method);
  const auto m =
      test::run_quiet(read_case(packed_tank(theta, boundary, bi ? "density_preserving" : method),
                                "corner_tank.yaml"),
                      1);
  EXPECT_NEAR(m["time_reached"].get<double>(), 0.3, 1e-9);
  EXPECT_EQ(m["particles_projected"].get<long>(), 0);
  EXPECT_EQ(m["escaped_particles"].get<long>(), 0);
  EXPECT_EQ(m["particles_removed"].get<long>(), 0);
  std::cout << fmt::format("corner tank {} {}: p_deep {:.4f} p_all {:.4f} contacts {} ke {:.2e}\n",
                           theta, method, m["pressure_l2_error_deep"].get<double>(),
                           m["pressure_l2_error"].get<double>(), m["wall_contacts"].get<long>(),
                           m["kinetic_energy_max"].get<double>());
  // Bounds: measured at 0.3 s plus a margin (docs/geometry.md, "Ghosts at sharp corners and
  // edges"). Ghosts, packed: 0.0074 (60), 0.0074 (90), 0.0077 (120 degrees; on the bare
  // lattice 0.240, 0.0069, 0.084), no wall contact. Integrals, packed with density_preserving
  // ghosts: 0.0142, 0.0251, 0.0169 (bounded loosely: their pressure terms are not this test's
  // subject). The ghost maps agree exactly on these flat faces.
  // The 120 degree tank gave 0.0888 (49 wall contacts) once the contact layer of
  // boundary/wall_impact.hpp landed: the packing's lid (a plane wall, relax_closure.hpp) met
  // the outward-leaning sides at 60 degrees with no corner images, the node-density packing
  // drew particles into those acute corners, and its wall clearance stacked two of them on one
  // point 0.012 dx from the side, inside the contact layer (0.1 dx), which threw them off at
  // t = 0 at 3.4 m/s. The lid and the polygon's sides now meet with the corner images of
  // flat_corners.hpp (the 60 degree dihedral images).
  // 75 and 100 degrees, angles no reflection group tiles: 0.0066 and 0.0078 (ghosts),
  // 0.0082 and 0.0070 (integrals), no wall contact, with the corner words cut at the exterior
  // bisector (flat_corners.hpp). With the single images alone (the gap round the bisector of
  // the corner and of the lid's 105 and 80 degree edges) the ghosts gave 0.334 (1610 wall
  // contacts) and 0.203 (544), the integrals 0.036 and 0.025 (their packing is the ghosts').
  const double bound = bi ? 0.2 : 0.02;
  if (!bi) {
    EXPECT_EQ(m["wall_contacts"].get<long>(), 0);
  }
  EXPECT_LT(m["pressure_l2_error_deep"].get<double>(), bound) << theta << " " << method;
}

INSTANTIATE_TEST_SUITE_P(AnglesAndMethods, CornerTank,
                         ::testing::Combine(::testing::Values(60, 75, 90, 100, 120),
                                            ::testing::Values("mirror", "mirror_beta",
                                                              "density_preserving", "integrals")),
                         [](const auto& info) {
                           return fmt::format("deg{}_{}", std::get<0>(info.param),
                                              std::get<1>(info.param));
                         });

}  // namespace
}  // namespace curvsph
