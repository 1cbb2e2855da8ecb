// The built `curvsph geometry` binary: columns and values of its CSV, and exit code 2 with
// the file, key or line named for bad input.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

#include "../support/command_fixture.hpp"

namespace {

namespace fs = std::filesystem;

class GeometryCommand : public curvsph::testing::CommandTest {
 protected:
  int run(const std::string& args) { return run_curvsph("geometry " + args); }
};

std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream ls(line);
    while (std::getline(ls, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

const std::vector<std::string> kHeader{"x",      "y",  "z",  "foot_x", "foot_y",
                                       "foot_z", "nx", "ny", "nz",     "distance",
                                       "k1",     "k2", "u",  "v",      "wall"};

TEST_F(GeometryCommand, Annulus2DToStdout) {
  const auto geom = write("g.yaml", R"(dimension: 2
name: ignored by the geometry command
walls:
  - {shape: circle, center: [0, 0], radius: 1, fluid: outside}
  - {shape: circle, center: [0, 0], radius: 2, fluid: inside}
  - {shape: box, min: [5, 5], max: [6, 6], fluid: outside}
)");
  const auto pts = write("p.csv", "x,y\n1.25,0\n\n0,1.875\n7,6\n");
  ASSERT_EQ(run(geom.string() + " --points " + pts.string()), 0) << err_;
  const auto rows = parse_csv(out_);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0], kHeader);
  for (const auto& r : rows) EXPECT_EQ(r.size(), kHeader.size());
  // Row 1: nearest is the inner circle (wall 0), fluid outside it: k = -1, u = 0.
  EXPECT_DOUBLE_EQ(std::stod(rows[1][3]), 1.0);
  EXPECT_DOUBLE_EQ(std::stod(rows[1][6]), 1.0);
  EXPECT_DOUBLE_EQ(std::stod(rows[1][9]), 0.25);
  EXPECT_DOUBLE_EQ(std::stod(rows[1][10]), -1.0);
  EXPECT_EQ(rows[1][2], "0");
  EXPECT_EQ(rows[1][11], "0");
  EXPECT_EQ(rows[1][12], "0");
  EXPECT_EQ(rows[1][13], "");
  EXPECT_EQ(rows[1][14], "0");
  // Row 2: the outer circle, fluid inside: k = 1/2, normal -y.
  EXPECT_EQ(rows[2][14], "1");
  EXPECT_DOUBLE_EQ(std::stod(rows[2][7]), -1.0);
  EXPECT_DOUBLE_EQ(std::stod(rows[2][10]), 0.5);
  EXPECT_DOUBLE_EQ(std::stod(rows[2][9]), 0.125);
  // Row 3: the box, which has no parameters.
  EXPECT_EQ(rows[3][14], "2");
  EXPECT_EQ(rows[3][12], "");
  EXPECT_DOUBLE_EQ(std::stod(rows[3][9]), 1.0);
}

TEST_F(GeometryCommand, Torus3DToFileWithFullPrecision) {
  const auto geom = write("g.yaml", R"(dimension: 3
walls:
  - {shape: torus, center: [0, 0, 0], axis: [0, 0, 1], major_radius: 1, minor_radius: 0.1,
     fluid: inside}
)");
  const auto pts = write("p.csv", "x,y,z\n1.05,0,0\n0,-0.95,0\n");
  const fs::path out = dir_ / "out.csv";
  ASSERT_EQ(run(geom.string() + " --points " + pts.string() + " --out " + out.string()), 0) << err_;
  EXPECT_EQ(out_, "");
  const auto rows = parse_csv(read(out));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], kHeader);
  EXPECT_EQ(rows[1][0], "1.05");
  EXPECT_DOUBLE_EQ(std::stod(rows[1][3]), 1.1);
  EXPECT_NEAR(std::stod(rows[1][9]), 0.05, 1e-15);
  EXPECT_DOUBLE_EQ(std::stod(rows[1][10]), 10.0);        // 1/a
  EXPECT_DOUBLE_EQ(std::stod(rows[1][11]), 1.0 / 1.1);   // cos 0 / (R + a)
  EXPECT_DOUBLE_EQ(std::stod(rows[2][11]), -1.0 / 0.9);  // inner equator: cos pi / (R - a)
  EXPECT_DOUBLE_EQ(std::stod(rows[2][13]), -std::numbers::pi / 2);  // v = phi
  EXPECT_EQ(rows[1][12], "0");                                      // u = theta
  EXPECT_DOUBLE_EQ(std::stod(rows[2][12]), std::numbers::pi);
  EXPECT_EQ(rows[1][3], "1.1000000000000001");  // %.17g: every double round-trips
}

TEST_F(GeometryCommand, BadGeometryFileExitsWith2) {
  const auto pts = write("p.csv", "x,y\n0,0\n");
  const auto geom = write("g.yaml",
                          "dimension: 2\nwalls:\n  - {shape: circle, center: [0, 0], "
                          "radius: -1, fluid: inside}\n");
  EXPECT_EQ(run(geom.string() + " --points " + pts.string()), 2);
  EXPECT_NE(err_.find("g.yaml: key 'walls.0.radius': must be > 0"), std::string::npos) << err_;

  const auto dim = write("d.yaml", "dimension: 4\nwalls: []\n");
  EXPECT_EQ(run(dim.string() + " --points " + pts.string()), 2);
  EXPECT_NE(err_.find("key 'dimension'"), std::string::npos) << err_;

  const auto syntax = write("s.yaml", "dimension: 2\nwalls: [\n");
  EXPECT_EQ(run(syntax.string() + " --points " + pts.string()), 2);
  EXPECT_NE(err_.find("YAML syntax error"), std::string::npos) << err_;

  EXPECT_EQ(run((dir_ / "missing.yaml").string() + " --points " + pts.string()), 2);
  EXPECT_NE(err_.find("cannot open file"), std::string::npos) << err_;
}

TEST_F(GeometryCommand, BadPointsFileExitsWith2) {
  const auto geom =
      write("g.yaml", "dimension: 2\nwalls: [{shape: plane, point: [0, 0], normal: [0, 1]}]\n");
  struct Bad {
    std::string csv, message;
  };
  const std::vector<Bad> bad{
      {"x,y,z\n0,0,0\n", "line 1: expected the header 'x,y'"},
      {"x,y\n0,0\n1,2,3\n", "line 3: expected 2 columns, got 3"},
      {"x,y\n0,0\n1\n", "line 3: expected 2 columns, got 1"},
      {"x,y\n0,abc\n", "line 2: column 'y': 'abc' is not a finite number"},
      {"x,y\n0,1e999\n", "line 2: column 'y'"},
      {"", "empty file"},
  };
  for (const auto& b : bad) {
    const auto pts = write("p.csv", b.csv);
    EXPECT_EQ(run(geom.string() + " --points " + pts.string()), 2) << b.csv;
    EXPECT_NE(err_.find(pts.string() + ": " + b.message), std::string::npos)
        << "stderr: " << err_ << " expected: " << b.message;
  }
}

}  // namespace
