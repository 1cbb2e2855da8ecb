// A wall concave seen from the fluid whose radius of curvature is below the kernel support 2h
// is refused at set-up (ghost_map.hpp, check_concave_support): exit 2 naming the file, the
// wall's key, the radius and 2h. Reference: the circle's radius (curvature 1/R exactly) and
// the support 2h = 2 h_over_dx dx of the case.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>
#include <vector>

#include "../support/quiet_run.hpp"
#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {
namespace {

TEST(ConcaveRefusal, RadiusBelowTheSupport) {
  // Fluid inside a circle of radius 0.1: refused for 2h = 0.15 with every map, accepted for
  // 2h = 0.1 (= R) and below.
  WallSet<2> tank;
  tank.add(std::make_shared<CircleWall>(Vec2d(0, 0), 0.1, FluidSide::inside));
  const std::vector<Vec2> x{Vec2(0.0, -0.09), Vec2(0.02, 0.0)};
  for (GhostMapKind map :
       {GhostMapKind::mirror, GhostMapKind::mirror_beta, GhostMapKind::density_preserving}) {
    try {
      check_ghost_walls(map, tank, 0.15, x, "case.yaml");
      FAIL() << "expected a refusal";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "case.yaml");
      EXPECT_EQ(e.key(), "walls.0");
      const std::string r = e.reason();
      EXPECT_NE(r.find("concave"), std::string::npos) << r;
      EXPECT_NE(r.find("radius of curvature 0.1 "), std::string::npos) << r;
      EXPECT_NE(r.find("2h = 0.15"), std::string::npos) << r;
      EXPECT_NE(r.find("h < 0.05"), std::string::npos) << r;
    }
    EXPECT_NO_THROW(check_ghost_walls(map, tank, 0.1, x, "case.yaml"));
  }
  // Only where fluid comes within the support: a 3-D ball of radius 0.1 with 2h = 0.15 is
  // refused; the same wall seen from outside (convex, an obstacle) is the convex check's.
  WallSet<3> ball;
  ball.add(std::make_shared<SphereWall>(Vec3d::Zero(), 0.1, FluidSide::inside));
  EXPECT_THROW(check_ghost_walls(GhostMapKind::mirror, ball, 0.15, {Vec3(0, 0, 0.05)}, "c"),
               InputError);
  EXPECT_NO_THROW(check_ghost_walls(GhostMapKind::mirror, ball, 0.09, {Vec3(0, 0, 0.05)}, "c"));
}

TEST(ConcaveRefusal, CaseExitsWithFileKeyRadiusAndSupport) {
  // A disk of water in a circle of radius 0.02 at dx = 0.01, h = 1.3 dx: 2h = 0.026 > 0.02.
  const auto node = [](double dx) {
    return YAML::Load(
        "{dimension: 2, resolution: {dx: " + std::to_string(dx) +
        ", h_over_dx: 1.3}, fluids: [{name: water, rho0: 1000, viscosity: 1.0e-3, "
        "region: {disk: {center: [0, 0], radius: 0.02}}}], eos: {type: linear, c0: 1}, "
        "walls: [{shape: circle, center: [0, 0], radius: 0.02, fluid: inside}], "
        "boundary: {method: ghost, map: mirror_beta}, time: {end: 0.0}, "
        "output: {every: 1, vtk: false}}");
  };
  try {
    test::run_quiet(read_case(node(0.01), "pipe.yaml"), 1);
    FAIL() << "expected exit 2";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "pipe.yaml");
    EXPECT_EQ(e.key(), "walls.0");
    const std::string r = e.reason();
    EXPECT_NE(r.find("radius of curvature 0.02 "), std::string::npos) << r;
    EXPECT_NE(r.find("2h = 0.026"), std::string::npos) << r;
  }
  // dx = 0.005: 2h = 0.013 < 0.02, accepted.
  EXPECT_NO_THROW(test::run_quiet(read_case(node(0.005), "pipe.yaml"), 1));
}

}  // namespace
}  // namespace curvsph
