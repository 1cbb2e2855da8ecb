// A short run of cases/droplet_wall.yaml (issue #6; the full study is
// `curvsph validate droplet_wall`): the drop starts as a half disk whose measured angle is far
// above the imposed 30 deg and has to spread towards it; its mass is conserved exactly and no
// particle crosses the NURBS wall.
#include <gtest/gtest.h>

#include "../support/quiet_run.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

TEST(RegressionDropletWall, DropSpreadsTowardsTheImposedAngle) {
  const Case c = read_case(std::string(CURVSPH_SOURCE_DIR) + "/cases/droplet_wall.yaml",
                           {"time.end=0.4", "output.vtk=false"});
  const auto m = test::run_quiet(c);
  EXPECT_EQ(m["droplet_mass_change"].get<double>(), 0.0);
  EXPECT_EQ(m["wall_crossings"].get<long>(), 0);
  EXPECT_NEAR(m["contact_angle_imposed_deg"].get<double>(), 30.0, 1e-9);
  const double initial = m["contact_angle_initial_deg"], now = m["contact_angle_deg"];
  EXPECT_GT(initial, 100.0);     // the half disk on the curved dip
  EXPECT_LT(now, initial - 25);  // it has moved a good part of the way
  // Both contact points see the same wall and the case is symmetric about x = 0.
  EXPECT_NEAR(m["contact_angle_deg_left"].get<double>(), m["contact_angle_deg_right"].get<double>(),
              2.0);
}

}  // namespace
}  // namespace curvsph
