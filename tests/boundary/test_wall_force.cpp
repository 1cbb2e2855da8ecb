// `boundary.wall_force` (boundary/wall_force.hpp) in both boundary models: a particle closer
// than 0.1 dx to a wall is pushed by (c0^2 / dx) (1 - d/d0)^2 along the wall normal, once per
// wall (a box corner pushes from both faces), and nothing else in the step changes. Reference:
// the closed-form law at the distances the test sets, and the same run without the option.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <map>
#include <string>

#include "../support/bi_tank.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

constexpr double kDx = 0.004, kC0 = 6.9;  // the BI test tank's (support/bi_tank.hpp)

// The law written out: d0 = 0.1 dx, (c0^2 / dx) (1 - d/d0)^2 for 0 < d < d0.
double law(double d) {
  const double d0 = 0.1 * kDx;
  return d < d0 ? kC0 * kC0 / kDx * std::pow(1 - d / d0, 2) : 0;
}

// Accelerations by particle id after the start-up force evaluation, with two particles moved
// next to the walls first: `floor_id` to 0.05 dx above the floor, `corner_id` to 0.02 dx from
// the left wall and 0.07 dx above the floor.
std::map<long, Vec2> accelerations(YAML::Node root, bool wall_force, long& floor_id,
                                   long& corner_id) {
  root["boundary"]["wall_force"] = wall_force;
  const Case c = read_case(root, "wall_force_test");
  Solver<2> first(c);
  first.initialize();
  Particles<2> P = first.particles();
  // The first-row particle at x ~ 0.05 and the bottom-left corner particle of the lattice.
  double best_floor = 1e9, best_corner = 1e9;
  std::size_t fi = 0, ci = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double x = P.x[i].x(), y = P.x[i].y();
    const double df = std::abs(x - 0.05) + y, dc = x + y;
    if (df < best_floor) best_floor = df, fi = i;
    if (dc < best_corner) best_corner = dc, ci = i;
  }
  P.x[fi].y() = static_cast<Real>(0.05 * kDx);
  P.x[ci] = Vec2(static_cast<Real>(0.02 * kDx), static_cast<Real>(0.07 * kDx));
  floor_id = static_cast<long>(P.id[fi]);
  corner_id = static_cast<long>(P.id[ci]);
  Solver<2> s(c);
  s.restart(P, 0);
  s.initialize();
  std::map<long, Vec2> a;
  for (std::size_t i = 0; i < s.particles().size(); ++i)
    a[static_cast<long>(s.particles().id[i])] = s.particles().a[i];
  return a;
}

void expect_law(const YAML::Node& root) {
  long floor_id = -1, corner_id = -1, f2 = -1, c2 = -1;
  const auto off = accelerations(YAML::Clone(root), false, floor_id, corner_id);
  const auto on = accelerations(YAML::Clone(root), true, f2, c2);
  ASSERT_EQ(floor_id, f2);
  ASSERT_EQ(corner_id, c2);
  ASSERT_EQ(off.size(), on.size());
  const Vec2 push_floor(0, static_cast<Real>(law(0.05 * kDx)));
  const Vec2 push_corner(static_cast<Real>(law(0.02 * kDx)), static_cast<Real>(law(0.07 * kDx)));
  ASSERT_GT(push_floor.y(), 2900);  // s = 1/2: a quarter of c0^2/dx = 11 902 m/s^2
  for (const auto& [id, a] : on) {
    const Vec2 diff = a - off.at(id);
    if (id == floor_id) {
      EXPECT_LT((diff - push_floor).norm(), 1e-9 * push_floor.norm());
    } else if (id == corner_id) {
      EXPECT_LT((diff - push_corner).norm(), 1e-9 * push_corner.norm());
    } else {
      EXPECT_EQ(diff.norm(), 0) << "particle " << id << " is farther than 0.1 dx from every wall";
    }
  }
}

TEST(WallForce, BoundaryIntegralsPushByTheLawOncePerWall) {
  expect_law(test::bi_tank("geometric"));
}

TEST(WallForce, GhostsPushByTheLawOncePerWall) {
  // Before, the ghost model ignored the key: a contact line in tension fell through the floor.
  YAML::Node root = test::bi_tank("geometric");
  root["boundary"] = YAML::Load("{method: ghost, map: mirror, velocity: no_slip}");
  expect_law(root);
}

}  // namespace
}  // namespace curvsph
