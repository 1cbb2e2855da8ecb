// cases/droplet_wall.yaml (Barker & Neethling §4.2, issue #6) started from the equilibrium
// shape of a non-wetting drop: a circular cap of radius 0.8 mm that meets the NURBS wall at
// 120 deg (centre (0, -0.157332 mm) found by bisection on the exact B-spline, area 0.93 of the
// case's half disk; domain.min.y moved so the cap's lattice lies on the ambient one). A
// contact-angle treatment that holds the imposed angle keeps it there; the measurement
// (analysis droplet_wall, circle fits at both contact points) reads 118.2 deg on this cap at
// t = 0. The first treatment (mirror colours, copied image normals, first row turned) let it
// run down to 111.1 deg by t = 0.4 s; the interface continued through the wall holds 119.5.
#include <gtest/gtest.h>

#include <filesystem>

#include "../support/quiet_run.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

TEST(DropletWall, EquilibriumCapAt120DegreesStaysThere) {
  const auto path = std::filesystem::path(CURVSPH_SOURCE_DIR) / "cases/droplet_wall.yaml";
  const Case c = read_case(
      path,
      {"walls.0.contact_angle=120", "fluids.1.region.disk.center=[0.0,-0.157332e-3]",
       "fluids.1.region.disk.radius=0.8e-3", "domain.min=[-4.0e-3,-1.457332e-3]", "time.end=0.4"});
  const auto m = test::run_quiet(c, 1);
  EXPECT_NEAR(m["contact_angle_initial_deg"].get<double>(), 120.0, 3.0);
  EXPECT_NEAR(m["contact_angle_deg_left"].get<double>(), 120.0, 3.0);
  EXPECT_NEAR(m["contact_angle_deg_right"].get<double>(), 120.0, 3.0);
  EXPECT_EQ(m["droplet_mass_change"].get<double>(), 0.0);
  EXPECT_EQ(m["wall_crossings"].get<long>(), 0);
}

}  // namespace
}  // namespace curvsph
