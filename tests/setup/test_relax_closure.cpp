// The walls of the ghost packing (setup/relax_closure.hpp): with free_faces: hold a box
// region's face that lies inside the walls becomes a plane wall; faces on or beyond a wall and
// faces across periodic axes do not. Reference: the tank's geometry by hand (the free surface
// y = H, normal -y).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/setup/relax_closure.hpp"

namespace curvsph {
namespace {

// A 60 degree tank (floor 0..2 at y = 0, sides leaning in to y = 0.7), fluid box to H = 0.5
// reaching past the sides.
YAML::Node tank(const std::string& free_faces) {
  return YAML::Load(
      "{dimension: 2, resolution: {dx: 0.05, h_over_dx: 2}, "
      "fluids: [{name: water, rho0: 1000, region: {box: {min: [-0.1, 0], max: [2.1, 0.5]}}}], "
      "walls: [{shape: nurbs_curve, degree: 1, fluid: left, knots: [0, 0, 1, 2, 3, 3], "
      "control_points: [[0.404145188433, 0.7], [0, 0], [2, 0], [1.595854811567, 0.7]]}], "
      "boundary: {method: ghost, map: mirror}, eos: {type: linear, c0: 1}, time: {end: 0.1}, "
      "setup: {relax: {free_faces: " +
      free_faces + "}}}");
}

TEST(RelaxClosure, HoldsTheFreeSurfaceOnly) {
  const Case c = read_case(tank("hold"), "tank.yaml");
  const WallSet<2> walls = parse_walls<2>(c.root["walls"], "tank.yaml", {});
  const WallSet<2> closure = relax_walls<2>(c, walls);
  ASSERT_EQ(closure.size(), 2u);  // the polygon and the free surface; not the floor or sides
  const WallPoint<2> p = closure[1].closest(Vec2d(1.0, 0.3));
  EXPECT_NEAR(p.distance, 0.2, 1e-12);
  EXPECT_NEAR(p.normal[0], 0.0, 1e-12);
  EXPECT_NEAR(p.normal[1], -1.0, 1e-12);
  // Open (the default): the walls alone.
  EXPECT_EQ(relax_walls<2>(read_case(tank("open"), "tank.yaml"), walls).size(), 1u);
}

TEST(RelaxClosure, HoldsANarrowTop) {
  // A V-tank whose sides lean in at 60 degrees from a floor 1 m wide, the box region reaching
  // 0.1 m past the floor's ends: at H = 0.5 the water's surface spans x in [0.289, 0.711], a
  // third of the face. Reference: the surface y = H by hand. Asking for most of the face left
  // it open (the 3-D wedge of the same sides: packed to the apex).
  YAML::Node n = tank("hold");
  n["fluids"][0]["region"]["box"] = YAML::Load("{min: [-0.1, 0], max: [1.1, 0.5]}");
  n["walls"][0]["control_points"] =
      YAML::Load("[[0.404145188433, 0.7], [0, 0], [1, 0], [0.595854811567, 0.7]]");
  const Case c = read_case(n, "v.yaml");
  const WallSet<2> walls = parse_walls<2>(c.root["walls"], "v.yaml", {});
  const WallSet<2> closure = relax_walls<2>(c, walls);
  ASSERT_EQ(closure.size(), 2u);
  EXPECT_NEAR(closure[1].closest(Vec2d(0.5, 0.3)).distance, 0.2, 1e-12);
}

TEST(RelaxClosure, SkipsPeriodicAxesAndFacesOnWalls) {
  // A channel periodic in x between plane walls at y = 0 and y = 0.2, the fluid box filling it
  // exactly: no face is free (x faces periodic, y faces on the walls). Cut to y = 0.1: the top
  // face is free.
  YAML::Node n = YAML::Load(
      "{dimension: 2, resolution: {dx: 0.02, h_over_dx: 1.3}, "
      "domain: {min: [0, 0], max: [1, 0.2], periodic: [true, false]}, "
      "fluids: [{name: water, rho0: 1000, region: {box: {min: [0, 0], max: [1, 0.2]}}}], "
      "walls: [{shape: plane, point: [0, 0], normal: [0, 1]}, "
      "{shape: plane, point: [0, 0.2], normal: [0, -1]}], "
      "boundary: {method: ghost, map: mirror}, eos: {type: linear, c0: 1}, time: {end: 0.1}, "
      "setup: {relax: {free_faces: hold}}}");
  const Case full = read_case(n, "channel.yaml");
  const WallSet<2> walls = parse_walls<2>(full.root["walls"], "channel.yaml", {});
  EXPECT_EQ(relax_walls<2>(full, walls).size(), 2u);
  n["fluids"][0]["region"]["box"]["max"][1] = 0.1;
  const WallSet<2> half = relax_walls<2>(read_case(n, "channel.yaml"), walls);
  ASSERT_EQ(half.size(), 3u);
  EXPECT_NEAR(half[2].closest(Vec2d(0.5, 0.04)).distance, 0.06, 1e-12);
}

}  // namespace
}  // namespace curvsph
