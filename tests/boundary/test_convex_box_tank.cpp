// Water at rest around a box standing on the floor of a 3-D tank (H/dx = 8, 0.3 s, packed with
// the free surface held, mirror ghosts, one thread): the box 0.6 x 0.4 x 0.4 m, its top edges
// and vertical edges convex seen from the water, its feet concave edges with the floor; as a
// `box` wall and as an STL mesh (fluid outside). Reference: the hydrostatic field rho0 g (H - z)
// of the run's own analysis, H = 0.8 m.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <iostream>
#include <string>

#include "../support/quiet_run.hpp"
#include "../support/test_meshes.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {
namespace {

YAML::Node box_on_floor(const std::string& obstacle) {
  return YAML::Load(fmt::format(
      "{{name: box_on_floor, dimension: 3, resolution: {{dx: 0.1, h_over_dx: 2}}, "
      "fluids: [{{name: water, rho0: 1000, viscosity: 1.0e-3, "
      "region: {{box: {{min: [0, 0, 0], max: [2.0, 1.2, 0.8]}}}}}}], "
      "initial: {{hydrostatic: {{depth: 0.8}}}}, eos: {{type: linear, c0: 28, p0: 0}}, "
      "density: {{method: continuity, delta_sph: 0.1}}, gravity: [0, 0, -9.81], "
      "walls: [{{shape: box, min: [0, 0, 0], max: [2.0, 1.2, 1.2], fluid: inside}}, {}], "
      "boundary: {{method: ghost, map: mirror}}, setup: {{relax: {{free_faces: hold}}}}, "
      "time: {{end: 0.3, cfl: 0.25}}, output: {{every: 0.3, vtk: false}}, "
      "analysis: {{hydrostatic: {{depth: 0.8}}}}}}",
      obstacle));
}

class ConvexBoxTank : public ::testing::TestWithParam<std::string> {};

TEST_P(ConvexBoxTank, StaysAtRest) {
  // Measured: 0.0108 of rho g H deep (box and STL alike, and a STEP box: 29 s, so not here),
  // no wall contact; the tank without the box 0.0102. Before (the closest point alone, the solid
  // near the box's edges covered two or three times): 0.0260 with 7436 wall contacts by 44
  // particles (box), 0.0362 with 3588 by 24 (STL); with the faces' shares but not yet turned with
  // the floor's corner images under the vertical edges: 0.0140 with 9464 contacts by 56 (box).
  // Bound: the 2 %.
  std::string obstacle = "{shape: box, min: [0.7, 0.4, 0], max: [1.3, 0.8, 0.4], fluid: outside}";
  std::filesystem::path dir;
  if (GetParam() == "stl") {
    dir = std::filesystem::temp_directory_path() /
          ("curvsph_convex_box_tank_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    testing::TestMesh m = testing::cube_mesh(1.0, 2);
    for (Vec3d& v : m.v) v = Vec3d(1.0, 0.6, 0.2) + Vec3d(0.3, 0.2, 0.2).cwiseProduct(v);
    testing::write_ascii_stl((dir / "box.stl").string(), m);
    obstacle =
        fmt::format("{{shape: cad, file: '{}', fluid: outside}}", (dir / "box.stl").string());
  }
  const auto m = test::run_quiet(read_case(box_on_floor(obstacle), "box_on_floor.yaml"), 1);
  if (!dir.empty()) std::filesystem::remove_all(dir);
  EXPECT_NEAR(m["time_reached"].get<double>(), 0.3, 1e-9);
  EXPECT_EQ(m["particles_projected"].get<long>(), 0);
  EXPECT_EQ(m["escaped_particles"].get<long>(), 0);
  EXPECT_EQ(m["particles_removed"].get<long>(), 0);
  EXPECT_EQ(m["wall_contacts"].get<long>(), 0);
  std::cout << fmt::format("box on the floor ({}): p_deep {:.4f} contacts {} ke {:.2e}\n",
                           GetParam(), m["pressure_l2_error_deep"].get<double>(),
                           m["wall_contacts"].get<long>(), m["kinetic_energy_max"].get<double>());
  EXPECT_LT(m["pressure_l2_error_deep"].get<double>(), 0.02);
}

INSTANTIATE_TEST_SUITE_P(Walls, ConvexBoxTank, ::testing::Values("box", "stl"));

}  // namespace
}  // namespace curvsph
