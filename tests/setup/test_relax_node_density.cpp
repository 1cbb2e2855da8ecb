// Relaxation (setup.relax) and the node-density analysis (Vela Vela §7) on small 2-D cases:
// relaxation reduces the node-density spread of random particles in a disk, and near a small
// circle wall the density_preserving ghosts keep the node density closer to the interior's
// than the mirror ghosts.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "../support/quiet_run.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"

namespace curvsph {
namespace {

// Fluid inside a circle of radius 0.3 (about 700 particles), started at random positions.
Case disk_case(const std::string& extra_setup) {
  YAML::Node root = YAML::Load(R"(
name: relax_disk
dimension: 2
resolution: {dx: 0.02, h_over_dx: 1.5}
domain: {min: [-0.32, -0.32], max: [0.32, 0.32]}
fluids:
  - {name: f, rho0: 1.0, region: {inside_walls: true, random: true}}
eos: {type: tait, c0: 10, gamma: 7, p0: 0}
walls:
  - {shape: circle, center: [0, 0], radius: 0.3, fluid: inside}
boundary: {method: ghost, map: density_preserving, velocity: free_slip}
time: {end: 0}
output: {vtk: false}
analysis: {node_density: {}}
)");
  root["setup"] = YAML::Load(extra_setup);
  return read_case(root, "relax_disk.yaml");
}

using test::run_quiet;

TEST(Relax, ReducesNodeDensitySpreadInDisk) {
  const auto m =
      run_quiet(disk_case("{random_seed: 3, relax: {max_steps: 300, tolerance: 1.0e-4}}"));
  const double before = m["relax_node_density_spread_initial"];
  const double after = m["relax_node_density_spread"];
  EXPECT_GT(before, 0.1);           // random positions: a wide spread
  EXPECT_LT(after, 0.25 * before);  // relaxation packs them
  EXPECT_LT(after, 0.03);
  EXPECT_GT(m["relax_steps"].get<long>(), 0);
}

TEST(NodeDensity, DensityPreservingCloserToInteriorThanMirrorNearCircle) {
  const auto m =
      run_quiet(disk_case("{random_seed: 5, relax: {max_steps: 300, tolerance: 1.0e-4}}"));
  const double mirror = m["ghost_node_density_dev_mirror"];
  const double dp = m["ghost_node_density_dev_density_preserving"];
  EXPECT_LT(dp, mirror);
  EXPECT_LT(dp, 0.05);
  EXPECT_DOUBLE_EQ(m["ghost_node_density_dev"].get<double>(), dp);  // the case's map
}

// Barker's Couette annulus (dx = 1.875 mm) from a lattice cut by the two circles and packed
// with the walls active. The lattice drops the points within 0.3 dx of the walls, and the
// packing spreads the rest over that strip: with masses rho0 dx^2 the fluid started up to
// 7.5 % below rho0, in tension (Tait with p0 = 2.5 Pa), and particles went through a wall
// (t = 0.21 s after these 300 packing steps, 0.24 s after 3000). With the packed volumes 1/n_i the
// summation density (the solver's own ghosts) is rho0 at t = 0 and the run keeps every particle
// inside.
TEST(Relax, PackedAnnulusStartsAtReferenceDensityAndStaysBetweenItsWalls) {
  YAML::Node root = YAML::Load(R"(
name: relax_annulus
dimension: 2
resolution: {dx: 1.875e-3, h_over_dx: 1.3}
domain: {min: [-0.041, -0.041], max: [0.041, 0.041]}
fluids:
  - {name: water, rho0: 1000, viscosity: 1.0e-3, region: {inside_walls: true}}
eos: {type: tait, c0: 0.25, gamma: 7, p0: 2.5}
density: {method: summation}
walls:
  - {shape: circle, center: [0, 0], radius: 0.025, fluid: outside,
     motion: {rotate: {omega: 1.0, center: [0, 0]}}}
  - {shape: circle, center: [0, 0], radius: 0.040, fluid: inside}
boundary: {method: ghost, map: mirror_beta, velocity: no_slip}
setup: {relax: {max_steps: 300, tolerance: 1.0e-4}}
time: {end: 0.35, cfl: 0.2}
output: {vtk: false}
analysis: {couette: {}}
)");
  const auto m = run_quiet(read_case(root, "relax_annulus.yaml"));
  EXPECT_LT(m["relax_node_density_spread"].get<double>(), 0.02);  // from 0.081
  EXPECT_LT(m["density_error_t0"].get<double>(), 1e-12);
  EXPECT_EQ(m["unstable"].get<int>(), 0);
  EXPECT_DOUBLE_EQ(m["time_reached"].get<double>(), 0.35);
}

}  // namespace
}  // namespace curvsph
