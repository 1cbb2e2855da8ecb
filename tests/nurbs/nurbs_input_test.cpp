// Every input error path names the key.
#include <gtest/gtest.h>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/geometry/nurbs_surface_wall.hpp"

using namespace curvsph;

namespace {
const char* kCurve = R"({shape: nurbs_curve, degree: 2,
  control_points: [[0, 0], [1, 1], [2, 0], [3, 1]], weights: [1, 0.5, 1, 1],
  knots: [0, 0, 0, 0.5, 1, 1, 1], fluid: left})";
const char* kSurface = R"({shape: nurbs_surface, degree: [1, 1],
  control_points: [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]],
  weights: [[1, 1], [1, 2]], knots_u: [0, 0, 1, 1], knots_v: [0, 0, 1, 1], fluid: front})";

std::string curve_error(const std::string& key, const std::string& value) {
  YAML::Node n = YAML::Load(kCurve);
  if (value.empty())
    n.remove(key);
  else
    n[key] = YAML::Load(value);
  try {
    make_nurbs_curve_wall(n, "case.yaml", "walls.2");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "case.yaml");
    return e.key();
  }
  return "<no error>";
}

std::string surface_error(const std::string& key, const std::string& value) {
  YAML::Node n = YAML::Load(kSurface);
  if (value.empty())
    n.remove(key);
  else
    n[key] = YAML::Load(value);
  try {
    make_nurbs_surface_wall(n, "case.yaml", "walls.1");
  } catch (const InputError& e) {
    return e.key();
  }
  return "<no error>";
}
}  // namespace

TEST(NurbsInput, ValidCurveAndSurfaceLoad) {
  EXPECT_NE(make_nurbs_curve_wall(YAML::Load(kCurve), "case.yaml", "walls.2"), nullptr);
  EXPECT_NE(make_nurbs_surface_wall(YAML::Load(kSurface), "case.yaml", "walls.1"), nullptr);
}

TEST(NurbsInput, CurveErrorsNameTheKey) {
  EXPECT_EQ(curve_error("knots", "[0, 0, 0, 1, 1, 1]"), "walls.2.knots");         // count
  EXPECT_EQ(curve_error("knots", "[0, 0, 0, 0.7, 0.5, 1, 1]"), "walls.2.knots");  // decreasing
  EXPECT_EQ(curve_error("knots", "[0, 0, 0, 1, 1, 1, 1]"), "walls.2.knots");      // multiplicity
  // A weight <= 0 is outside the schema's range for each element (io/schema_table.cpp).
  EXPECT_EQ(curve_error("weights", "[1, 0, 1, 1]"), "walls.2.weights.1");
  EXPECT_EQ(curve_error("weights", "[1, -2, 1, 1]"), "walls.2.weights.1");
  EXPECT_EQ(curve_error("weights", "[1, 1, 1]"), "walls.2.weights");  // count
  EXPECT_EQ(curve_error("knots", ""), "walls.2.knots");               // missing
  EXPECT_EQ(curve_error("degree", ""), "walls.2.degree");
  EXPECT_EQ(curve_error("control_points", ""), "walls.2.control_points");
  EXPECT_EQ(curve_error("fluid", ""), "walls.2.fluid");
  EXPECT_EQ(curve_error("fluid", "inside"), "walls.2.fluid");       // unknown side
  EXPECT_EQ(curve_error("degree", "4"), "walls.2.control_points");  // too few points
  EXPECT_EQ(curve_error("control_points", "[[0, 0], [1, 1, 2], [2, 0], [3, 1]]"),
            "walls.2.control_points.1");
  EXPECT_EQ(curve_error("colour", "red"), "walls.2.colour");  // unknown key
}

TEST(NurbsInput, SurfaceErrorsNameTheKey) {
  EXPECT_EQ(surface_error("knots_u", "[0, 0, 1]"), "walls.1.knots_u");
  EXPECT_EQ(surface_error("knots_v", "[0, 1, 0.5, 1]"), "walls.1.knots_v");
  EXPECT_EQ(surface_error("weights", "[[1, 1], [0, 2]]"), "walls.1.weights.1.0");
  EXPECT_EQ(surface_error("weights", "[[1, 1]]"), "walls.1.weights");
  EXPECT_EQ(surface_error("knots_v", ""), "walls.1.knots_v");
  EXPECT_EQ(surface_error("fluid", "left"), "walls.1.fluid");
  EXPECT_EQ(surface_error("degree", "[1]"), "walls.1.degree");
  EXPECT_EQ(surface_error("control_points", "[[[0, 0, 0], [0, 1, 0]], [[1, 0, 0]]]"),
            "walls.1.control_points.1");
}
