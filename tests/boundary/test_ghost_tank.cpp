// Ghost walls under gravity with a free surface: the small tank of support/bi_tank.hpp (12 rows
// of water, h = 2 dx, continuity density with delta-SPH, no-slip mirror ghosts) held to
// t sqrt(g/H) = 20. Reference: the analytic hydrostatic field p = rho0 g (H - y) of the run's
// analysis. Two ghost-model fixes are needed together (ghost_boundary.cpp, ghosts.hpp): the
// free-slip image in the continuity equation and `boundary.ghost_pressure: hydrostatic`.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "../support/bi_tank.hpp"
#include "../support/quiet_run.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"

namespace curvsph {
namespace {

YAML::Node ghost_tank(const std::string& ghost_pressure) {
  YAML::Node root = test::bi_tank("geometric");
  root["boundary"] = YAML::Load(
      "{method: ghost, map: mirror, velocity: no_slip, ghost_pressure: " + ghost_pressure + "}");
  root["time"]["end"] = 1.4;  // t sqrt(g/H) = 20
  root["time"]["max_steps"] = 0;
  return root;
}

nlohmann::json run(const YAML::Node& root) {
  // One thread: ~5000 short steps; beside another multi-threaded test under `ctest -j 2` on 2
  // cores, each OpenMP barrier waits for a descheduled thread (measured: minutes, not seconds).
  return test::run_quiet(read_case(root, "ghost_tank_test"), 1);
}

TEST(GhostTank, HydrostaticGhostPressureKeepsTheTankAtRest) {
  const auto m = run(ghost_tank("hydrostatic"));
  EXPECT_GT(m["t_end_reached"].get<double>(), 19.99);
  EXPECT_EQ(m["escaped_particles"].get<long>(), 0);
  // Measured: KE max 1.5e-7 M g H (2.6e-7 before the walls' impact pressure and contact
  // layer, boundary/wall_impact.hpp), pressure error 0.018 of rho0 g H (12 rows: the
  // lattice's own discretisation error). Before those terms, with the no-slip image in the
  // continuity equation as well, two particles crossed a wall at t = 0.85 s; with `copy`, the
  // corner particle at t = 0.11 s.
  EXPECT_LT(m["kinetic_energy_max"].get<double>(), 2e-6);
  EXPECT_LT(m["pressure_l2_error"].get<double>(), 0.025);
}

TEST(GhostTank, CopiedPressureLetsTheCornerSinkOntoTheContactLayer) {
  // The default for flows driven by a body force along a periodic axis (ghost_boundary.cpp):
  // under gravity the first row's wall push is short by 2 rho g d, and the corner particle
  // sinks. It used to cross the floor at t = 0.11 s; the walls' contact layer
  // (boundary/wall_impact.hpp) now holds it at dx/4, without the stray-particle contact and
  // with boundary.penetration: stop, and the tank moves an order of magnitude more than with
  // the hydrostatic ghost pressure (measured: KE max 2.6e-6 M g H against 1.5e-7, pressure
  // error 0.022 against 0.018).
  YAML::Node root = ghost_tank("copy");
  root["boundary"]["penetration"] = "stop";
  root["boundary"]["contact"] = 0;
  const auto m = run(root);
  EXPECT_GT(m["t_end_reached"].get<double>(), 19.99);
  EXPECT_EQ(m["particles_projected"].get<long>(), 0);
  EXPECT_EQ(m["escaped_particles"].get<long>(), 0);
  EXPECT_GT(m["kinetic_energy_max"].get<double>(), 1e-6);  // hydrostatic: 1.5e-7 (above)
}

TEST(GhostTank, HydrostaticGhostPressureIsTheDefaultUnderGravity) {
  YAML::Node root = test::bi_tank("geometric");
  root["boundary"] = YAML::Load("{method: ghost}");
  EXPECT_EQ(read_case(root, "ghost_tank_test").boundary.ghost_pressure, "hydrostatic");
  root["density"] = YAML::Node();
  root.remove("density");
  EXPECT_EQ(read_case(root, "ghost_tank_test").density.method, DensitySpec::Method::continuity);
}

TEST(GhostTank, GhostPressureKeyIsForGhostsOnly) {
  YAML::Node root = test::bi_tank("geometric");
  root["boundary"]["ghost_pressure"] = "hydrostatic";
  EXPECT_THROW(read_case(root, "ghost_tank_test"), InputError);
  EXPECT_THROW(read_case(ghost_tank("linear"), "ghost_tank_test"), InputError);
}

}  // namespace
}  // namespace curvsph
