// parse_walls: every error path names the file, the key path and the reason; good files
// give the same walls as the constructors, with their motion.
#include <gtest/gtest.h>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/torus.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/yaml_read.hpp"

namespace curvsph {
namespace {

template <int D>
WallSet<D> parse(const std::string& walls_yaml) {
  return parse_walls<D>(YAML::Load(walls_yaml), "geom.yaml", ".");
}

// Parses `walls_yaml` (the value of `walls:`) in dimension D and expects an InputError at
// `key` whose reason contains `reason`.
template <int D>
void expect_error(const std::string& walls_yaml, const std::string& key,
                  const std::string& reason) {
  SCOPED_TRACE(walls_yaml);
  try {
    parse<D>(walls_yaml);
    ADD_FAILURE() << "no error; expected one at " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "geom.yaml");
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("geom.yaml: key '" + key + "'"), std::string::npos);
  }
}

const std::string kCircle = "{shape: circle, center: [0, 0], radius: 1, fluid: inside";

TEST(GeometryParser, StructureErrors) {
  expect_error<2>("{a: 1}", "walls", "expected a list");
  expect_error<2>("[3]", "walls.0", "expected a map");
  expect_error<2>("[{center: [0, 0]}]", "walls.0.shape", "missing key");
  expect_error<2>("[{shape: [circle]}]", "walls.0.shape", "expected a string");
  expect_error<2>("[{shape: hexagon}]", "walls.0.shape", "unknown shape 'hexagon'");
  expect_error<2>("[" + kCircle + ", colour: red}]", "walls.0.colour", "unknown key");
  expect_error<2>("[" + kCircle + "}, {shape: circle, center: [0, 0], fluid: inside}]",
                  "walls.1.radius", "missing key");
}

TEST(GeometryParser, ShapeNotInThisDimension) {
  expect_error<2>("[{shape: torus}]", "walls.0.shape", "not available in 2-D");
  expect_error<2>("[{shape: sphere}]", "walls.0.shape", "not available in 2-D");
  expect_error<3>("[{shape: circle}]", "walls.0.shape", "not available in 3-D");
  expect_error<3>("[{shape: ellipse}]", "walls.0.shape", "not available in 3-D");
  expect_error<2>("[{shape: nurbs_surface}]", "walls.0.shape", "not available in 2-D");
}

TEST(GeometryParser, NurbsAndCadShapesAreWired) {
  // A rational quadratic unit circle (9 control points, w = sqrt(2)/2 at the corners), fluid
  // on the left of increasing parameter = inside: a point at radius 0.5 is 0.5 from the wall.
  const std::string w = "0.7071067811865476";
  const std::string circle =
      "[{shape: nurbs_curve, degree: 2, fluid: left, control_points: [[1, 0], [1, 1], [0, 1], "
      "[-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]], weights: [1, " +
      w + ", 1, " + w + ", 1, " + w + ", 1, " + w +
      ", 1], knots: [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]}]";
  const WallSet<2> walls = parse<2>(circle);
  const auto p = walls.closest(Vec2d(0.3, 0.4));
  EXPECT_NEAR(p.distance, 0.5, 1e-9);
  EXPECT_NEAR(p.k1, 1.0, 1e-9);
  expect_error<3>("[{shape: cad, file: no_such_part.step, fluid: inside}]", "walls.0.file",
                  "not found");
  expect_error<3>("[{shape: nurbs_surface, fluid: front}]", "walls.0.degree", "");
}

TEST(GeometryParser, WrongTypes) {
  expect_error<2>("[{shape: circle, center: [0, 0], radius: abc, fluid: inside}]", "walls.0.radius",
                  "expected a finite number, got 'abc'");
  expect_error<2>("[{shape: circle, center: [0, 0], radius: [1], fluid: inside}]", "walls.0.radius",
                  "expected a number");
  expect_error<2>("[{shape: circle, center: [0, x], radius: 1, fluid: inside}]", "walls.0.center.1",
                  "expected a finite number");
  expect_error<2>("[{shape: circle, center: 5, radius: 1, fluid: inside}]", "walls.0.center",
                  "expected a list of 2 numbers");
  expect_error<2>("[{shape: circle, center: [0, 0, 0], radius: 1, fluid: inside}]",
                  "walls.0.center", "expected a list of 2 numbers, got a list of 3");
  expect_error<3>("[{shape: sphere, center: [0, 0], radius: 1, fluid: inside}]", "walls.0.center",
                  "expected a list of 3 numbers, got a list of 2");
  expect_error<2>("[{shape: circle, center: [0, 0], radius: 1, fluid: sideways}]", "walls.0.fluid",
                  "expected one of inside | outside");
  expect_error<2>("[{shape: circle, center: [0, 0], radius: .inf, fluid: inside}]",
                  "walls.0.radius", "finite");
}

TEST(GeometryParser, InvalidValues) {
  expect_error<2>("[{shape: circle, center: [0, 0], radius: 0, fluid: inside}]", "walls.0.radius",
                  "must be > 0");
  expect_error<3>("[{shape: sphere, center: [0, 0, 0], radius: -2, fluid: inside}]",
                  "walls.0.radius", "must be > 0");
  expect_error<2>("[{shape: plane, point: [0, 0], normal: [0, 0]}]", "walls.0.normal", "non-zero");
  expect_error<3>(
      "[{shape: cylinder, point: [0, 0, 0], axis: [0, 0, 0], radius: 1, fluid: inside}]",
      "walls.0.axis", "non-zero");
  expect_error<3>(
      "[{shape: torus, center: [0, 0, 0], axis: [0, 0, 0], major_radius: 2, minor_radius: 1, "
      "fluid: inside}]",
      "walls.0.axis", "non-zero");
  expect_error<2>("[{shape: box, min: [0, 1], max: [1, 1], fluid: inside}]", "walls.0.max",
                  "min must be < max");
  expect_error<3>("[{shape: box, min: [0, 0, 2], max: [1, 1, 1], fluid: outside}]", "walls.0.max",
                  "axis 2");
  expect_error<3>(
      "[{shape: torus, center: [0, 0, 0], axis: [0, 0, 1], major_radius: 1, minor_radius: 1, "
      "fluid: outside}]",
      "walls.0.minor_radius", "self-intersects");
  expect_error<2>("[{shape: ellipse, center: [0, 0], semi_axes: [1, 0], fluid: inside}]",
                  "walls.0.semi_axes.1", "must be > 0");
}

TEST(GeometryParser, MotionErrors) {
  expect_error<2>("[" + kCircle + ", motion: {spin: {omega: 1}}}]", "walls.0.motion.spin",
                  "unknown key");
  expect_error<2>("[" + kCircle + ", motion: {rotate: {center: [0, 0]}}}]",
                  "walls.0.motion.rotate.omega", "missing key");
  expect_error<2>(
      "[" + kCircle + ", motion: {rotate: {omega: 1, center: [0, 0], axis: [0, 0, 1]}}}]",
      "walls.0.motion.rotate.axis", "unknown key");
  expect_error<2>("[" + kCircle +
                      ", motion: {rotate: {omega: 1, center: [0, 0]}, translate: {velocity: [1, "
                      "0]}}}]",
                  "walls.0.motion", "exactly one");
  expect_error<2>("[" + kCircle + ", motion: {translate: {velocity: [1, 0, 0]}}}]",
                  "walls.0.motion.translate.velocity", "list of 2 numbers");
  expect_error<3>(
      "[{shape: sphere, center: [0, 0, 0], radius: 1, fluid: inside, motion: {rotate: {omega: "
      "1, center: [0, 0, 0], axis: [0, 0, 0]}}}]",
      "walls.0.motion.rotate.axis", "non-zero");
}

TEST(GeometryParser, GoodFile2D) {
  const WallSet<2> set = parse<2>(R"([
    {shape: circle, center: [0, 0], radius: 0.025, fluid: outside,
     motion: {rotate: {omega: 2.0, center: [0, 0]}}},
    {shape: circle, center: [0, 0], radius: 0.040, fluid: inside},
    {shape: ellipse, center: [1, 0], semi_axes: [0.2, 0.1], fluid: outside,
     motion: {translate: {velocity: [0.5, 0]}}},
    {shape: plane, point: [0, -1], normal: [0, 1]},
    {shape: box, min: [-2, -2], max: [2, 2], fluid: inside}])");
  ASSERT_EQ(set.size(), 5u);
  EXPECT_EQ(set[0].motion.kind, WallMotion<2>::Kind::rotate);
  EXPECT_NEAR((set[0].motion.velocity_at(Vec2d(0.025, 0)) - Vec2d(0, 0.05)).norm(), 0, 1e-15);
  EXPECT_EQ(set[1].motion.kind, WallMotion<2>::Kind::none);
  EXPECT_EQ(set[2].motion.kind, WallMotion<2>::Kind::translate);
  const CircleWall ref(Vec2d(0, 0), 0.040, FluidSide::inside);
  const Vec2d x(0.03, 0.01);
  EXPECT_EQ(set[1].closest(x).distance, ref.closest(x).distance);
  EXPECT_EQ(set.closest(Vec2d(0.028, 0)).wall, 0);
  EXPECT_EQ(set.closest(Vec2d(0.038, 0)).wall, 1);
}

TEST(GeometryParser, GoodFile3D) {
  const WallSet<3> set = parse<3>(R"([
    {shape: torus, center: [0, 0, 0], axis: [0, 0, 2], major_radius: 1, minor_radius: 0.25,
     fluid: inside, motion: {rotate: {omega: 1, center: [0, 0, 0], axis: [0, 0, 1]}}},
    {shape: cylinder, point: [0, 0, 0], axis: [1, 0, 0], radius: 0.1, fluid: outside},
    {shape: sphere, center: [3, 0, 0], radius: 0.5, fluid: outside},
    {shape: plane, point: [0, 0, -1], normal: [0, 0, 1]},
    {shape: box, min: [-3, -3, -3], max: [4, 3, 3], fluid: inside}])");
  ASSERT_EQ(set.size(), 5u);
  const TorusWall ref(Vec3d(0, 0, 0), Vec3d(0, 0, 1), 1, 0.25, FluidSide::inside);
  const Vec3d x(0.9, 0.2, 0.1);
  EXPECT_EQ(set[0].closest(x).k2, ref.closest(x).k2);
  EXPECT_NEAR((set[0].motion.velocity_at(Vec3d(1, 0, 0)) - Vec3d(0, 1, 0)).norm(), 0, 1e-15);
  EXPECT_EQ(set[0].describe().rfind("torus", 0), 0u);
}

TEST(GeometryParser, ShapeNames) {
  const auto two = wall_shape_names<2>();
  const auto three = wall_shape_names<3>();
  EXPECT_EQ(two, (std::vector<std::string>{"box", "circle", "ellipse", "nurbs_curve", "plane"}));
  EXPECT_EQ(three, (std::vector<std::string>{"box", "cad", "cylinder", "nurbs_surface", "plane",
                                             "sphere", "torus"}));
}

TEST(GeometryYamlRead, HelpersNameKeyAndReason) {
  const YAML::Node n = YAML::Load("{steps: 2.5, flag: maybe, mode: fast, list: [1, 2], m: {a: 1}}");
  auto expect = [](auto&& f, const std::string& key, const std::string& reason) {
    try {
      f();
      ADD_FAILURE() << "no error at " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key);
      EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
    }
  };
  expect([&] { yaml::read_key(n, "steps", "c.yaml", "run", yaml::read_integer); }, "run.steps",
         "expected an integer");
  expect([&] { yaml::read_key(n, "flag", "c.yaml", "run", yaml::read_bool); }, "run.flag",
         "expected true or false");
  expect(
      [&] {
        yaml::read_choice(n["mode"], {"slow", "exact"}, "c.yaml", "run.mode");
      },
      "run.mode", "expected one of slow | exact, got 'fast'");
  expect([&] { yaml::read_numbers(n["list"], "c.yaml", "run.list", 3); }, "run.list",
         "got a list of 2");
  expect([&] { yaml::check_keys(n["m"], {"b"}, "c.yaml", "run.m"); }, "run.m.a",
         "unknown key (allowed here: b)");
  expect([&] { yaml::child(n, "nope", "c.yaml", "run"); }, "run.nope", "missing key");
  expect([&] { yaml::read_nonnegative(YAML::Load("-1"), "c.yaml", "x"); }, "x", ">= 0");
  expect([&] { yaml::read_string(n["m"], "c.yaml", "run.m"); }, "run.m", "expected a string");
  EXPECT_EQ(yaml::read_key(n, "steps", "c.yaml", "run", yaml::read_positive), 2.5);
  EXPECT_EQ(yaml::join("", "walls"), "walls");
  EXPECT_EQ(yaml::join("walls", std::size_t{3}), "walls.3");
}

}  // namespace
}  // namespace curvsph
