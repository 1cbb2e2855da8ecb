// STL walls through the built `curvsph geometry`: ASCII and binary files read, curvatures
// reported, and exit code 2 naming the STL file and the reason for a truncated file, a
// binary count that does not match the size, non-finite vertices and surfaces that do not
// bound a volume.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/command_fixture.hpp"
#include "../support/test_meshes.hpp"

namespace {

using curvsph::Vec3d;
using curvsph::testing::TestMesh;

TestMesh tetrahedron() {
  TestMesh m;
  const Vec3d p[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Vec3d c = (p[0] + p[1] + p[2] + p[3]) / 4;
  m.add(p[0], p[1], p[2], c);
  m.add(p[0], p[1], p[3], c);
  m.add(p[0], p[2], p[3], c);
  m.add(p[1], p[2], p[3], c);
  return m;
}

class StlWall : public curvsph::testing::CommandTest {
 protected:
  // Runs `curvsph geometry` on one STL wall and the points; returns the exit code.
  int geometry(const std::string& stl, const std::string& fluid, const std::string& points) {
    const auto g = write("g.yaml", "dimension: 3\nwalls:\n  - {shape: cad, file: " + stl +
                                       ", fluid: " + fluid + "}\n");
    const auto p = write("p.csv", "x,y,z\n" + points);
    return run_curvsph("geometry " + g.string() + " --points " + p.string());
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Expects exit 2 with the STL's name and every fragment in the message.
  void expect_refused(const std::string& stl, const std::vector<std::string>& fragments,
                      const std::string& fluid = "inside") {
    EXPECT_EQ(geometry(stl, fluid, "0.1,0.1,0.1\n"), 2) << err_;
    EXPECT_NE(err_.find(stl), std::string::npos) << err_;
    for (const auto& f : fragments) EXPECT_NE(err_.find(f), std::string::npos) << f << "\n" << err_;
  }
  std::vector<std::vector<double>> rows() const {  // the numeric rows of out_
    std::vector<std::vector<double>> r;
    std::istringstream in(out_);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      std::vector<double> row;
      std::istringstream ls(line);
      std::string cell;
      while (std::getline(ls, cell, ',')) row.push_back(cell.empty() ? NAN : std::stod(cell));
      r.push_back(row);
    }
    return r;
  }
};

TEST_F(StlWall, AsciiTetrahedronDistances) {
  curvsph::testing::write_ascii_stl(path("t.stl"), tetrahedron());
  ASSERT_EQ(geometry("t.stl", "outside", "0.1,0.2,-0.5\n0.1,0.1,0.1\n"), 0) << err_;
  const auto r = rows();
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0][9], 0.5, 1e-12);   // below the face z = 0, fluid outside
  EXPECT_NEAR(r[1][9], -0.1, 1e-12);  // inside, nearest the three coordinate faces
  EXPECT_NEAR(r[0][10], 0, 1e-12);    // flat faces, sharp edges: no curvature
}

TEST_F(StlWall, BinarySphereReportsItsCurvature) {
  const double R = 0.5;
  curvsph::testing::write_binary_stl(path("s.stl"), curvsph::testing::uv_sphere(R, 2.0));
  ASSERT_EQ(geometry("s.stl", "inside", "0,0,0.25\n0.2,-0.1,0.3\n"), 0) << err_;
  for (const auto& row : rows()) {
    const Vec3d x(row[0], row[1], row[2]);
    EXPECT_NEAR(row[9], R - x.norm(), 2e-4);  // within the facets' depth R (1 - cos 1.4 deg)
    EXPECT_NEAR(row[10] * R, 1.0, 0.03);      // k1 = k2 = 1/R, concave seen from inside
    EXPECT_NEAR(row[11] * R, 1.0, 0.03);
  }
}

TEST_F(StlWall, TruncatedAsciiIsRefused) {
  curvsph::testing::write_ascii_stl(path("t.stl"), tetrahedron());
  std::ifstream in(path("t.stl"));
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  write("cut.stl", text.substr(0, text.find("vertex", text.find("facet", 200))));
  expect_refused("cut.stl", {"inside a facet", "truncated"});
  write("noend.stl", text.substr(0, text.rfind("endsolid")));
  expect_refused("noend.stl", {"without `endsolid`"});
}

TEST_F(StlWall, BinaryCountNotMatchingTheSizeIsRefused) {
  curvsph::testing::write_binary_stl(path("b.stl"), tetrahedron(), 5);
  expect_refused("b.stl", {"declares 5 triangles", "take 334 bytes", "has 284 bytes"});
}

TEST_F(StlWall, NonFiniteVerticesAreRefused) {
  TestMesh m = tetrahedron();
  m.v[2].y() = std::numeric_limits<double>::quiet_NaN();
  curvsph::testing::write_ascii_stl(path("nan.stl"), m);
  expect_refused("nan.stl", {"non-finite vertex", "line "});
  m = tetrahedron();
  m.v[1].x() = std::numeric_limits<double>::infinity();
  curvsph::testing::write_binary_stl(path("inf.stl"), m);
  expect_refused("inf.stl", {"non-finite vertex", "triangle "});
}

TEST_F(StlWall, SurfacesThatDoNotBoundAVolumeAreRefused) {
  TestMesh one;
  one.t.push_back({one.vertex({0, 0, 0}), one.vertex({1, 0, 0}), one.vertex({0, 1, 0})});
  curvsph::testing::write_ascii_stl(path("one.stl"), one);
  for (const char* fluid : {"inside", "outside"})
    expect_refused("one.stl", {"3 edge(s) used by one triangle only", "e.g. from ("}, fluid);

  TestMesh holed = curvsph::testing::uv_sphere(1.0, 30.0);
  holed.t.erase(holed.t.begin() + 20);
  curvsph::testing::write_binary_stl(path("holed.stl"), holed);
  expect_refused("holed.stl", {"3 edge(s) used by one triangle only"});

  // Two tetrahedra sharing one edge only: every edge used twice except that one, used 4 times.
  TestMesh two = tetrahedron();
  const Vec3d q[3] = {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};  // with (0, 0, 0): the mirror image
  const Vec3d c = (q[0] + q[1] + q[2]) / 4;
  two.add({0, 0, 0}, q[0], q[1], c);
  two.add({0, 0, 0}, q[0], q[2], c);
  two.add({0, 0, 0}, q[1], q[2], c);
  two.add(q[0], q[1], q[2], c);
  curvsph::testing::write_ascii_stl(path("two.stl"), two);
  expect_refused("two.stl", {"1 edge(s) shared by three triangles or more"});

  TestMesh flipped = tetrahedron();
  std::swap(flipped.t[0][1], flipped.t[0][2]);
  curvsph::testing::write_ascii_stl(path("flipped.stl"), flipped);
  expect_refused("flipped.stl", {"3 edge(s) walked twice in the same direction"});

  TestMesh inward = tetrahedron();
  for (auto& T : inward.t) std::swap(T[1], T[2]);
  curvsph::testing::write_ascii_stl(path("inward.stl"), inward);
  expect_refused("inward.stl", {"face inward"});
}

}  // namespace
