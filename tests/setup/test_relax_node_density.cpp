// Relaxation (setup.relax) and the node-density analysis (Vela Vela §7) on small 2-D cases:
// relaxation reduces the node-density spread of random particles in a disk, and near a small
// circle wall the density_preserving ghosts keep the node density closer to the interior's
// than the mirror ghosts.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

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

nlohmann::json run_quiet(const Case& c) {
  RunOptions o;
  o.write_files = false;
  o.progress = false;
  return run_case(c, o);
}

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

}  // namespace
}  // namespace curvsph
