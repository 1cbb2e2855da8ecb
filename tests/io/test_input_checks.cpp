// Bad input found by trying careless and hostile values (issue 34): each is an exit 2 (or an
// InputError) naming the file and the key — duplicate keys, echoed input clipped, NURBS data
// that gave a zero normal or NaN curvature, a contact angle `geometry` accepted and `run`
// refused, a CAD scale that gave infinite distances, a STEP face dropped for its negative
// radius, `shepard --h inf` — and `curvsph keys` prints the schema's keys and defaults.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <BRepPrimAPI_MakeCylinder.hxx>
#include <STEPControl_Writer.hxx>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "../support/command_fixture.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/case_schema.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

class InputChecks : public testing::CommandTest {
 protected:
  // `curvsph geometry` on a geometry file of `dim` with the one wall `wall`.
  int geometry(int dim, const std::string& wall) {
    const auto geom =
        write("g.yaml", "dimension: " + std::to_string(dim) + "\nwalls:\n  - " + wall + "\n");
    const auto pts = write("p.csv", dim == 2 ? "x,y\n0.5,0.2\n" : "x,y,z\n0,0,0\n");
    return run_curvsph("geometry " + geom.string() + " --points " + pts.string());
  }
  // The error line names g.yaml and `key`, and contains `reason`.
  void expect_named(const std::string& key, const std::string& reason) {
    EXPECT_NE(err_.find("g.yaml: key '" + key + "'"), std::string::npos) << err_;
    EXPECT_NE(err_.find(reason), std::string::npos) << err_;
  }
};

const std::string kCurve =
    "{shape: nurbs_curve, degree: 1, control_points: [[0, 0], [1, 0], [1, 1]], "
    "knots: [0, 0, 0.5, 1, 1], fluid: left";

TEST_F(InputChecks, ValidNurbsCurveRuns) {
  ASSERT_EQ(geometry(2, kCurve + "}"), 0) << err_;
}

TEST_F(InputChecks, NurbsCurveWithAllControlPointsEqual) {
  EXPECT_EQ(geometry(2,
                     "{shape: nurbs_curve, degree: 1, control_points: [[1, 1], [1, 1], [1, 1]], "
                     "knots: [0, 0, 0.5, 1, 1], fluid: left}"),
            2);
  expect_named("walls.0.control_points", "coincide");
}

TEST_F(InputChecks, NurbsWeights) {
  EXPECT_EQ(geometry(2, kCurve + ", weights: [1, 1e300, 1]}"), 2);
  expect_named("walls.0.weights.1", "<= 1e100");
  // Within the range, but a ratio of 1e16 collapses the curve onto one control point.
  EXPECT_EQ(geometry(2, kCurve + ", weights: [1e-8, 1e8, 1]}"), 2);
  expect_named("walls.0.weights", "largest / smallest weight");
  EXPECT_EQ(geometry(2, kCurve + ", weights: [1, 0, 1]}"), 2);
  expect_named("walls.0.weights.1", ">= 1e-100");
}

TEST_F(InputChecks, NurbsKnotSpans) {
  EXPECT_EQ(geometry(2,
                     "{shape: nurbs_curve, degree: 1, control_points: [[0, 0], [1, 0], [1, 1]], "
                     "knots: [0, 0, 1e-300, 1, 1], fluid: left}"),
            2);
  expect_named("walls.0.knots", "below 1e-12 of the parameter range");
  EXPECT_EQ(geometry(2,
                     "{shape: nurbs_curve, degree: 1, control_points: [[0, 0], [1, 0], [1, 1]], "
                     "knots: [0, 0, 1e-300, 2e-300, 2e-300], fluid: left}"),
            2);
  expect_named("walls.0.knots", "too narrow");
  EXPECT_EQ(geometry(2,
                     "{shape: nurbs_curve, degree: 1, control_points: [[0, 0], [1, 0], [1, 1]], "
                     "knots: [0, 0, 1, 0.5, 1], fluid: left}"),
            2);
  expect_named("walls.0.knots", "decrease");
}

TEST_F(InputChecks, NurbsTolerance) {
  EXPECT_EQ(geometry(2, kCurve + ", tolerance: -1}"), 2);
  expect_named("walls.0.tolerance", ">= 0");
  EXPECT_EQ(geometry(2, kCurve + ", tolerance: .nan}"), 2);
  expect_named("walls.0.tolerance", "finite");
  EXPECT_EQ(geometry(2, kCurve + ", tolerance: NaN}"), 2);
  expect_named("walls.0.tolerance", "finite");
}

TEST_F(InputChecks, NurbsSurfaceWithAllControlPointsEqual) {
  EXPECT_EQ(geometry(3,
                     "{shape: nurbs_surface, degree: [1, 1], control_points: [[[1, 1, 1], [1, 1, "
                     "1]], [[1, 1, 1], [1, 1, 1]]], knots_u: [0, 0, 1, 1], knots_v: [0, 0, 1, 1], "
                     "fluid: front}"),
            2);
  expect_named("walls.0.control_points", "coincide");
}

// `geometry` refuses the contact angle `run` refuses (one check, in the wall parser).
TEST_F(InputChecks, ContactAngleOutOfRange) {
  EXPECT_EQ(geometry(2,
                     "{shape: circle, center: [0, 0], radius: 1, fluid: inside, "
                     "contact_angle: 200}"),
            2);
  expect_named("walls.0.contact_angle", "< 180");
  ASSERT_EQ(geometry(2,
                     "{shape: circle, center: [0, 0], radius: 1, fluid: inside, "
                     "contact_angle: 60}"),
            0)
      << err_;
}

TEST_F(InputChecks, CadScaleOutOfRange) {
  EXPECT_EQ(geometry(3, "{shape: cad, file: part.step, scale: 1e300, fluid: inside}"), 2);
  expect_named("walls.0.scale", "<= 1e6");
  EXPECT_EQ(geometry(3, "{shape: cad, file: part.step, scale: -1, fluid: inside}"), 2);
  expect_named("walls.0.scale", ">= 1e-6");
}

// OpenCASCADE drops a STEP face whose cylinder has a negative radius without an error; the
// reader names the file and the face instead.
TEST_F(InputChecks, StepFaceWithNegativeRadius) {
  const fs::path good = dir_ / "cyl.step";
  STEPControl_Writer w;
  ASSERT_EQ(w.Transfer(BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape(), STEPControl_AsIs),
            IFSelect_RetDone);
  ASSERT_EQ(w.Write(good.c_str()), IFSelect_RetDone);
  const std::string text = read(good);
  const std::regex cyl(R"((CYLINDRICAL_SURFACE\('[^']*',#\d+,)([0-9.E+-]+)\))");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, cyl)) << text;
  write("neg.step",
        std::regex_replace(text, cyl, "$1-$2)", std::regex_constants::format_first_only));
  // The file as written reads.
  EXPECT_NO_THROW(parse_walls<3>(YAML::Load("[{shape: cad, file: cyl.step, fluid: inside}]"),
                                 "case.yaml", dir_));
  try {
    parse_walls<3>(YAML::Load("[{shape: cad, file: neg.step, fluid: inside}]"), "case.yaml", dir_);
    FAIL() << "a face with a negative radius was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "case.yaml");
    EXPECT_EQ(e.key(), "walls.0.file");
    EXPECT_NE(e.reason().find("neg.step"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("CYLINDRICAL_SURFACE with radius -"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("face #"), std::string::npos) << e.what();
  }
  EXPECT_EQ(geometry(3, "{shape: cad, file: neg.step, fluid: inside}"), 2);
  expect_named("walls.0.file", "CYLINDRICAL_SURFACE with radius -");
}

TEST_F(InputChecks, ShepardOptionsMustBeFinite) {
  const auto geom = write("g.yaml",
                          "dimension: 2\nwalls:\n  - {shape: circle, center: [0, 0], "
                          "radius: 1, fluid: inside}\n");
  const auto pts = write("p.csv", "x,y\n0.5,0\n");
  const std::string base =
      "shepard " + geom.string() + " --points " + pts.string() + " --mode geometric";
  EXPECT_EQ(run_curvsph(base + " --h inf --dx 0.05"), 2);
  EXPECT_NE(err_.find("--h"), std::string::npos) << err_;
  EXPECT_NE(err_.find("finite number > 0"), std::string::npos) << err_;
  EXPECT_EQ(run_curvsph(base + " --h nan --dx 0.05"), 2);
  EXPECT_EQ(run_curvsph(base + " --h 0.1 --dx -inf"), 2);
  EXPECT_NE(err_.find("--dx"), std::string::npos) << err_;
  ASSERT_EQ(run_curvsph(base + " --h 0.1 --dx 0.05"), 0) << err_;
}

TEST_F(InputChecks, DuplicateKeyInCaseAndGeometryFile) {
  const auto c = write("case.yaml", R"(dimension: 2
resolution: {dx: 0.1}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids: [{rho0: 1000, region: {box: {min: [0, 0], max: [1, 1]}}}]
eos: {c0: 10}
time: {end: 0.01}
time: {end: 5}
)");
  EXPECT_EQ(
      run_curvsph("run " + c.string() + " --out " + (dir_ / "o").string() + " --threads 1 --quiet"),
      2);
  EXPECT_NE(err_.find("case.yaml: key 'time': duplicate key (again on line 7)"), std::string::npos)
      << err_;
  EXPECT_EQ(geometry(2, "{shape: circle, center: [0, 0], radius: 1, radius: 2, fluid: inside}"), 2);
  expect_named("walls.0.radius", "duplicate key");
}

// A 10 MB CSV cell and raw bytes in a YAML value come back clipped and escaped.
TEST_F(InputChecks, EchoedInputIsClippedAndEscaped) {
  const auto geom = write("g.yaml",
                          "dimension: 2\nwalls:\n  - {shape: circle, center: [0, 0], "
                          "radius: 1, fluid: inside}\n");
  const auto pts = write("p.csv", "x,y\n" + std::string(10'000'000, '7') + "z,0\n");
  EXPECT_EQ(run_curvsph("geometry " + geom.string() + " --points " + pts.string()), 2);
  EXPECT_LT(err_.size(), 400u) << err_.substr(0, 400);
  EXPECT_NE(err_.find(std::string(80, '7') + "... (10000001 bytes)"), std::string::npos)
      << err_.substr(0, 400);

  const auto bad = write("b.yaml",
                         "dimension: 2\nwalls:\n  - {shape: circle, center: [0, 0], "
                         "radius: 1, fluid: \"in\\x01side\\xe9\"}\n");
  EXPECT_EQ(run_curvsph("geometry " + bad.string() + " --points " + pts.string()), 2);
  EXPECT_NE(err_.find("'in\\x01side\\xc3\\xa9'"), std::string::npos) << err_;
}

// `curvsph keys boundary` prints every boundary.* key with the table's default, and the
// defaults are those the parser takes (test_case_schema.cpp: ParsedDefaultsEqualTheTable).
TEST_F(InputChecks, KeysCommandListsBoundaryKeys) {
  ASSERT_EQ(run_curvsph("keys boundary"), 0) << err_;
  int n = 0;
  for (const auto& k : schema::keys()) {
    if (k.path.rfind("boundary.", 0) != 0) continue;
    ++n;
    const auto at = out_.find(k.path + "\n");
    ASSERT_NE(at, std::string::npos) << k.path << "\n" << out_;
    const auto l1 = at + k.path.size() + 1;  // the line of type, range, default and unit
    const std::string line = out_.substr(l1, out_.find('\n', l1) - l1);
    EXPECT_NE(line.find("default: " + k.fallback), std::string::npos) << line;
  }
  EXPECT_GE(n, 10);
  EXPECT_NE(out_.find("boundary.contact\n    number in [0, 0.5); default: 0.1; unit: dx"),
            std::string::npos)
      << out_;
  EXPECT_EQ(out_.find("time.cfl"), std::string::npos);
  EXPECT_EQ(run_curvsph("keys bondary"), 2);
  EXPECT_NE(err_.find("bondary"), std::string::npos) << err_;
  ASSERT_EQ(run_curvsph("keys --markdown"), 0);
  EXPECT_EQ(out_, schema::render_markdown());
}

}  // namespace
}  // namespace curvsph
