// The walls in the output (io/walls_vtp.hpp) and forces.csv (io/forces_csv.hpp): the
// tessellation of a circle and a sphere against their exact geometry, wall names (defaults,
// duplicates refused), and a run's series.pvd with one named block per wall, read by VTK's own
// Python module, beside forces.csv with its columns.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>

#include "../support/command_fixture.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/forces_csv.hpp"
#include "curvsph/io/pvd_series.hpp"
#include "curvsph/io/walls_vtp.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

// A circle of radius R at dx: one closed polyline of about 2 pi R / dx vertices, every one on
// the circle to round-off.
TEST(WallsOutput, CircleIsOneClosedPolylineOnTheCircle) {
  const double R = 0.05, dx = 0.004;
  const Vec2d c(0.3, -0.2);
  const CircleWall wall(c, R, FluidSide::inside);
  const WallMesh<2> m = tessellate_walls<2>({&wall}, dx, Eigen::AlignedBox<double, 2>());
  const double n = 2 * std::numbers::pi * R / dx;  // 78.5
  EXPECT_LE(std::abs(static_cast<double>(m.points.size()) - n), 1.0);
  for (const auto& p : m.points) EXPECT_LT(std::abs((p - c).norm() - R), 1e-12 * R);
  ASSERT_EQ(m.offsets.size(), 1u);
  ASSERT_EQ(m.connectivity.size(), m.points.size() + 1);
  EXPECT_EQ(m.connectivity.front(), m.connectivity.back());
  std::set<std::int64_t> used(m.connectivity.begin(), m.connectivity.end());
  EXPECT_EQ(used.size(), m.points.size());
  ASSERT_EQ(m.velocity.size(), m.points.size());
}

// A sphere: triangles whose vertices lie on the sphere, covering its area to the chords'
// error (the inscribed polyhedron: about (dx/R)^2 / 12 short).
TEST(WallsOutput, SphereTrianglesLieOnTheSphere) {
  const double R = 0.05, dx = 0.005;
  const Vec3d c(0.1, 0, -0.1);
  const SphereWall wall(c, R, FluidSide::outside);
  const WallMesh<3> m = tessellate_walls<3>({&wall}, dx, Eigen::AlignedBox<double, 3>());
  ASSERT_GT(m.offsets.size(), 100u);
  for (const auto& p : m.points) EXPECT_LT(std::abs((p - c).norm() - R), 1e-12 * R);
  double area = 0;
  for (std::size_t t = 0; t < m.offsets.size(); ++t) {
    EXPECT_EQ(m.offsets[t], static_cast<std::int64_t>(3 * (t + 1)));
    const auto& a = m.points[static_cast<std::size_t>(m.connectivity[3 * t])];
    const auto& b = m.points[static_cast<std::size_t>(m.connectivity[3 * t + 1])];
    const auto& d = m.points[static_cast<std::size_t>(m.connectivity[3 * t + 2])];
    area += 0.5 * (b - a).cross(d - a).norm();
  }
  EXPECT_NEAR(area / (4 * std::numbers::pi * R * R), 1.0, 0.01);
  // Shared vertices are merged: a closed triangulated sphere has V - E + F = 2, E = 3F/2.
  const double F = static_cast<double>(m.offsets.size());
  EXPECT_EQ(static_cast<double>(m.points.size()) - 1.5 * F + F, 2.0);
}

TEST(WallsOutput, NamesDefaultToTheirPlaceAndMustBeUnique) {
  const YAML::Node walls = YAML::Load(R"([
  {shape: circle, center: [0, 0], radius: 1, fluid: inside},
  {shape: circle, center: [0, 0], radius: 0.2, fluid: outside, name: cylinder,
   moment_center: [0.5, 0]}])");
  const WallSet<2> set = parse_walls<2>(walls, "w.yaml", ".");
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set[0].name, "wall0");
  EXPECT_EQ(set[1].name, "cylinder");
  EXPECT_EQ(set[1].moment_center, Vec2d(0.5, 0));
  const WallGroups g = WallGroups::of(set);
  EXPECT_EQ(g.names, (std::vector<std::string>{"wall0", "cylinder"}));
  EXPECT_EQ(load_components(2), (std::vector<std::string>{"fx", "fy", "mz"}));
  EXPECT_EQ(load_components(3).size(), 6u);

  YAML::Node dup = YAML::Clone(walls);
  dup[0]["name"] = "cylinder";
  try {
    parse_walls<2>(dup, "w.yaml", ".");
    FAIL() << "a duplicate name was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("walls.1.name"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("duplicate"), std::string::npos) << e.what();
  }
  YAML::Node clash = YAML::Clone(walls);
  clash[1]["name"] = "wall0";  // the first wall's default name
  EXPECT_THROW(parse_walls<2>(clash, "w.yaml", "."), InputError);
  YAML::Node comma = YAML::Clone(walls);
  comma[1]["name"] = "a,b";
  EXPECT_THROW(parse_walls<2>(comma, "w.yaml", "."), InputError);
}

class WallsRun : public testing::CommandTest {};

// The plane channel (two plane walls, ghosts): series.pvd lists, at every output time, one
// block per wall named after it (walls_0.vtp and walls_1.vtp, written once: nothing moves),
// polylines that VTK reads; forces.csv has `time` and NAME.fx, NAME.fy, NAME.mz per wall at
// the output times (the probe times by default).
TEST_F(WallsRun, SeriesHasANamedBlockPerWallAndForcesCsv) {
  const fs::path out = dir_ / "out";
  const std::string cmd = "run " +
                          (fs::path(CURVSPH_SOURCE_DIR) / "cases" / "poiseuille_2d.yaml").string() +
                          " -q --threads 1 --out " + out.string() +
                          " --set time.end=0.004 --set output.every=0.002 --set walls.1.name=top";
  ASSERT_EQ(run_curvsph(cmd), 0) << err_;
  std::map<int, std::set<std::string>> files;
  std::map<int, std::string> names;
  std::map<int, int> count;
  for (const auto& e : io::PvdSeries::read(out / "series.pvd")) {
    files[e.part].insert(e.file);
    names[e.part] = e.name;
    ++count[e.part];
  }
  EXPECT_EQ(names[2], "wall0");
  EXPECT_EQ(names[3], "top");
  EXPECT_EQ(files[2], std::set<std::string>{"walls_0.vtp"});
  EXPECT_EQ(files[3], std::set<std::string>{"walls_1.vtp"});
  EXPECT_EQ(count[2], 3);  // t = 0, 0.002, 0.004
  EXPECT_EQ(count[3], 3);

  std::ifstream csv(out / "forces.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header, "time,wall0.fx,wall0.fy,wall0.mz,top.fx,top.fy,top.mz");
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 3);
  const auto m = nlohmann::json::parse(read(out / "metrics.json"));
  EXPECT_TRUE(m.contains("forces.top.fy"));
  EXPECT_TRUE(m.contains("forces_mean.wall0.fx"));

  // VTK reads the wall blocks as polylines: the clipped plane y = 0 from x = 0 to 5e-4.
  const std::string py = "/usr/bin/python3 " + std::string(CURVSPH_SOURCE_DIR) +
                         "/tests/io/read_series_vtk.py " + (out / "series.pvd").string() + " >" +
                         (dir_ / "vtk.json").string() + " 2>" + (dir_ / "vtk.err").string();
  const int status = std::system(py.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 4) GTEST_SKIP() << "python3-vtk9 is not installed";
  ASSERT_EQ(code, 0) << read(dir_ / "vtk.err");
  const auto vtk = nlohmann::json::parse(read(dir_ / "vtk.json"));
  int walls = 0;
  for (const auto& e : vtk) {
    if (e["part"].get<int>() < 2) continue;
    ++walls;
    EXPECT_EQ(e["lines"], 1);
    EXPECT_GE(e["points"].get<long>(), 16);  // 5e-4 / 3.125e-5 segments + 1
    EXPECT_TRUE(e["arrays"].contains("velocity"));
  }
  EXPECT_EQ(walls, 6);

  // output.forces_every: 0 writes no forces.csv.
  ASSERT_EQ(run_curvsph(cmd + " --overwrite --set output.forces_every=0"), 0) << err_;
  EXPECT_FALSE(fs::exists(out / "forces.csv"));
}

}  // namespace
}  // namespace curvsph
