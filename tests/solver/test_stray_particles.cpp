// One stray particle is handled and counted, never fatal (solver/stray_particles.hpp): the
// density clamp, the projection of a particle found past a wall, the removal of a particle
// that left the domain, and the counters of metrics.json. References: the exact closest
// points of a circle and a box, and particle positions advanced by hand.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <memory>

#include "../support/quiet_run.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/solver/stray_particles.hpp"

namespace curvsph {
namespace {

TEST(StrayParticles, DensityIsClampedToItsFluidsRangeAndCounted) {
  Particles<2> P;
  P.resize(5);
  const std::vector<Real> rho0{1000, 1};
  const Real rho[5] = {500, 1000, 1400, Real(0.2), 1};
  const int phase[5] = {0, 0, 0, 1, 1};
  for (int i = 0; i < 5; ++i) {
    P.rho[i] = rho[i];
    P.phase[i] = phase[i];
  }
  EXPECT_EQ(clamp_density<2>(P, 5, rho0, Real(0.7), Real(1.3)), 3);
  EXPECT_DOUBLE_EQ(P.rho[0], 700);
  EXPECT_DOUBLE_EQ(P.rho[1], 1000);
  EXPECT_DOUBLE_EQ(P.rho[2], 1300);
  EXPECT_NEAR(P.rho[3], 0.7, 1e-12);
  EXPECT_DOUBLE_EQ(P.rho[4], 1);
}

TEST(StrayParticles, ParticleInsideACircularObstacleIsPutBackAlongTheNormal) {
  WallSet<2> walls;
  walls.add(std::make_shared<CircleWall>(Vec2d(0, 0), 1.0, FluidSide::outside));
  Vec<2> x(Real(0.9) * std::cos(Real(0.3)), Real(0.9) * std::sin(Real(0.3)));  // 0.1 inside
  const Vec<2> radial(std::cos(Real(0.3)), std::sin(Real(0.3)));
  const Vec<2> tangent(-radial.y(), radial.x());
  Vec<2> v = Real(-2) * radial + Real(0.5) * tangent;  // moving into the obstacle
  ASSERT_EQ(project_out_of_walls<2>(walls, x, v, 0.01), WallFix::projected);
  EXPECT_NEAR(x.norm(), 1.01, 1e-12);                   // depth 0.01 outside the circle
  EXPECT_NEAR(x.normalized().dot(radial), 1.0, 1e-12);  // along the normal
  EXPECT_NEAR(v.dot(radial), 0.0, 1e-12);               // normal velocity removed
  EXPECT_NEAR(v.dot(tangent), 0.5, 1e-12);              // tangential velocity kept
  // Moving away from the wall: the velocity is kept.
  Vec<2> x2(0, Real(0.95)), v2(0, 1);
  ASSERT_EQ(project_out_of_walls<2>(walls, x2, v2, 0.01), WallFix::projected);
  EXPECT_NEAR(v2.y(), 1.0, 1e-12);
  // Closer than the contact distance on the fluid side: stopped there (a contact).
  Vec<2> x4(0, Real(1.004)), v4(Real(0.3), -2);
  ASSERT_EQ(project_out_of_walls<2>(walls, x4, v4, 0.01), WallFix::contact);
  EXPECT_NEAR(x4.y(), 1.01, 1e-12);
  EXPECT_NEAR(v4.y(), 0.0, 1e-12);
  EXPECT_NEAR(v4.x(), 0.3, 1e-6);
  // Farther than the contact distance: nothing moves.
  Vec<2> x3(0, 2), v3(0, -1);
  EXPECT_EQ(project_out_of_walls<2>(walls, x3, v3, 0.01), WallFix::none);
  EXPECT_EQ(x3, Vec<2>(0, 2));
}

TEST(StrayParticles, ParticlePastATankCornerEndsInsideTheTank) {
  WallSet<3> walls;
  walls.add(std::make_shared<BoxWall<3>>(Vec3d(0, 0, 0), Vec3d(1, 1, 1), FluidSide::inside));
  Vec<3> x(-0.01, -0.02, 0.5), v(-1, -1, 0.3);
  ASSERT_EQ(project_out_of_walls<3>(walls, x, v, 0.005), WallFix::projected);
  EXPECT_GT(walls.closest(x.cast<double>()).distance, 0.0);
  EXPECT_GE(v.x(), 0);
  EXPECT_GE(v.y(), 0);
  EXPECT_NEAR(v.z(), 0.3, 1e-12);
}

TEST(StrayParticles, RemovalBoxIsTheDomainOrTheGrownParticleAndTankBox) {
  const std::vector<Vec<2>> x{Vec<2>(0, 0), Vec<2>(1, 0.5)};
  const WallSet<2> none;
  const auto own =
      removal_box<2>(false, Vec3d::Zero(), Vec3d::Zero(), {false, false, false}, x, none, 0.1);
  EXPECT_FALSE(own.outside(Vec<2>(-0.9, 1.4)));  // grown by the largest extent (1)
  EXPECT_TRUE(own.outside(Vec<2>(-1.1, 0)));
  WallSet<2> tank;  // a tank 4 long: the fluid may reach all of it, and beyond by 4
  tank.add(std::make_shared<BoxWall<2>>(Vec2d(0, 0), Vec2d(4, 1), FluidSide::inside));
  const auto in_tank =
      removal_box<2>(false, Vec3d::Zero(), Vec3d::Zero(), {false, false, false}, x, tank, 0.1);
  EXPECT_FALSE(in_tank.outside(Vec<2>(7.9, 0.5)));
  EXPECT_TRUE(in_tank.outside(Vec<2>(8.1, 0.5)));
  const auto dom =
      removal_box<2>(true, Vec3d(0, 0, 0), Vec3d(1, 1, 0), {true, false, false}, x, none, 0.1);
  EXPECT_FALSE(dom.outside(Vec<2>(5, 0.5)));  // periodic axis: never
  EXPECT_TRUE(dom.outside(Vec<2>(0.5, 1.01)));
}

// A tank that is not a box wall (a degree-1 NURBS polygon 4 long, the water in its first metre)
// bounds the removal box as the box wall does: the water that runs along the tank stays in the
// run. Before, only box walls counted, and a dam break over a step in a polygon tank lost its
// front at x = 2 (the particles' box [0, 1] grown by 1).
TEST(StrayParticles, RemovalBoxHoldsEveryBoundedWall) {
  const std::vector<Vec<2>> x{Vec<2>(0.1, 0.1), Vec<2>(1, 0.5)};
  const WallSet<2> polygon = parse_walls<2>(YAML::Load(R"(
- shape: nurbs_curve
  degree: 1
  control_points: [[0, 1], [0, 0], [2, 0], [2, 0.3], [4, 0.3], [4, 1]]
  knots: [0, 0, 1, 2, 3, 4, 5, 5]
  fluid: left
)"),
                                            "geom.yaml", ".");
  const auto in_tank =
      removal_box<2>(false, Vec3d::Zero(), Vec3d::Zero(), {false, false, false}, x, polygon, 0.1);
  // The box of the particles and the polygon, [0, 4] x [0, 1], grown by 4 on every side.
  EXPECT_FALSE(in_tank.outside(Vec<2>(7.9, 0.5)));
  EXPECT_TRUE(in_tank.outside(Vec<2>(8.1, 0.5)));
  EXPECT_FALSE(in_tank.outside(Vec<2>(1, -3.9)));
  EXPECT_TRUE(in_tank.outside(Vec<2>(1, 5.1)));
  // An infinite wall adds nothing beyond the particles' own grown box.
  WallSet<2> floor = parse_walls<2>(YAML::Load("[{shape: plane, point: [0, 0], normal: [0, 1]}]"),
                                    "geom.yaml", ".");
  const auto on_floor =
      removal_box<2>(false, Vec3d::Zero(), Vec3d::Zero(), {false, false, false}, x, floor, 0.1);
  EXPECT_FALSE(on_floor.outside(Vec<2>(1.9, 0.5)));
  EXPECT_TRUE(on_floor.outside(Vec<2>(2.1, 0.5)));
}

// 5 x 5 particles at x = 0.81 ... 0.89 moving at 10 m/s towards the domain's edge at x = 1,
// with a sound speed of 1 m/s so that pressure barely changes their paths (|a| ~ c0^2/h):
// after 0.012 s only the column at 0.89 has passed x = 1.
YAML::Node leaving_case() {
  return YAML::Load(R"(
dimension: 2
resolution: {dx: 0.02, h_over_dx: 1.3}
domain: {min: [0, 0], max: [1, 1]}
fluids: [{rho0: 1000, region: {box: {min: [0.8, 0.4], max: [0.9, 0.5]}}, velocity: [10, 0]}]
eos: {type: tait, c0: 1}
time: {end: 0.012, cfl: 0.2}
)");
}

TEST(StrayParticles, ParticlesThatLeaveTheDomainAreRemovedAndCounted) {
  YAML::Node root = leaving_case();
  root["time"]["max_removed_fraction"] = 0.5;
  const auto m = test::run_quiet(read_case(root, "leaving"), 1);
  EXPECT_EQ(m["particles_initial"].get<long>(), 25);
  EXPECT_EQ(m["particles_removed"].get<long>(), 5);
  EXPECT_EQ(m["particles"].get<long>(), 25);  // the count the run started with
  EXPECT_EQ(m["particles_projected"].get<long>(), 0);
  EXPECT_NEAR(m["time_reached"].get<double>(), 0.012, 1e-12);
}

TEST(StrayParticles, MoreThanTheAllowedFractionRemovedStopsTheRun) {
  // Default max_removed_fraction 0.01: 5 of 25 is too many.
  EXPECT_THROW(test::run_quiet(read_case(leaving_case(), "leaving"), 1), InstabilityError);
}

TEST(StrayParticles, SummationDensityOfAFreeBlobIsClampedNotFatal) {
  // A free square of fluid with summation density: its edge particles see a third to a half
  // of a full support, rho < 0.7 rho0 (the corners: a quarter of it). Summation is asked for
  // (the default, continuity, starts every particle at rho0).
  YAML::Node root = leaving_case();
  root["fluids"][0]["velocity"] = YAML::Load("[0, 0]");
  root["time"]["end"] = 0.002;
  root["density"] = YAML::Load("{method: summation}");
  const auto m = test::run_quiet(read_case(root, "blob"), 1);
  const long clamped = m["density_clamped"].get<long>();
  EXPECT_GT(clamped, 0);
  EXPECT_EQ(m["particles_removed"].get<long>(), 0);
  root["density"] =
      YAML::Load("{method: summation, clamp: [0.9, 1.1]}");  // a narrower range clamps more
  EXPECT_GT(test::run_quiet(read_case(root, "blob"), 1)["density_clamped"].get<long>(), clamped);
  root["density"] = YAML::Load("{method: summation, clamp: false}");
  EXPECT_EQ(test::run_quiet(read_case(root, "blob"), 1)["density_clamped"].get<long>(), 0);
  root["density"] = YAML::Load("{clamp: [1.2, 1.3]}");
  EXPECT_THROW(read_case(root, "blob"), InputError);
}

}  // namespace
}  // namespace curvsph
