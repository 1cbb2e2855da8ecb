// Smooth faces of a triangle mesh (STL) split at feature edges, each answering alone
// (TriMeshWall::face_points_near, the MultiFace of geometry/faceted.hpp), so that ghosts treat a
// mesh's sharp edges as a CAD solid's. References: the analytic box (the feet are the point's
// projections on the planes of the faces it is near, the normals the axes) and the `box` wall
// itself in a tank at rest (the same ghosts, so the same run).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <memory>

#include "../support/quiet_run.hpp"
#include "../support/test_meshes.hpp"
#include "curvsph/geometry/trimesh_wall.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {
namespace {

TEST(TriMeshFaces, CubeIsSixFlatFacesEachAnsweringAlone) {
  const double h = 0.5;  // the cube [-h, h]^3, 4 x 4 quads a side (triangles across them)
  const auto m = testing::cube_mesh(h, 4);
  for (auto side : {TriMeshWall::Side::inside, TriMeshWall::Side::outside}) {
    const TriMeshWall wall(m.v, m.t, side);
    EXPECT_EQ(wall.face_count(), 6);
    const double s = side == TriMeshWall::Side::inside ? 1.0 : -1.0;
    // Inside near the corner (h, h, h), near the edge x = y = -h, and mid-face near z = -h;
    // outside beside the face x = h (within reach of that face only).
    const std::vector<Vec3d> probes =
        side == TriMeshWall::Side::inside
            ? std::vector<Vec3d>{{0.45, 0.42, 0.47}, {-0.46, -0.41, 0.1}, {0.03, -0.02, -0.44}}
            : std::vector<Vec3d>{{0.55, 0.1, -0.2}};
    for (const Vec3d& x : probes) {
      std::array<WallPoint<3>, 8> fp;
      const double reach = 0.2;
      const int n = wall.face_points_near(x, reach, fp.data(), 8);
      // The reference: every face plane within reach, with the foot inside the face.
      int expected = 0;
      for (int a = 0; a < 3; ++a)
        for (double sign : {-1.0, 1.0}) {
          const double d = s * (h - sign * x[a]);  // > 0 on the fluid side
          if (std::abs(d) >= reach) continue;
          ++expected;
          Vec3d foot = x;
          foot[a] = sign * h;
          const Vec3d normal = -s * sign * Vec3d::Unit(a);
          bool found = false;
          for (int k = 0; k < n; ++k) {
            const WallPoint<3>& p = fp[static_cast<std::size_t>(k)];
            if ((p.foot - foot).norm() > 1e-12) continue;
            found = true;
            EXPECT_LT((p.normal - normal).norm(), 1e-12) << x.transpose();
            EXPECT_NEAR(p.distance, d, 1e-12) << x.transpose();
            EXPECT_EQ(p.k1, 0.0);
            EXPECT_EQ(p.k2, 0.0);
          }
          EXPECT_TRUE(found) << "face " << a << sign << " at " << x.transpose();
        }
      EXPECT_EQ(n, expected) << x.transpose();
    }
  }
}

TEST(TriMeshFaces, Float32CubeFacesAreStillPlanar) {
  // A binary STL stores float32 vertices: a cube off the origin, 8 x 8 quads a side, its
  // vertices rounded to float (relative error 6e-8): still 6 planar faces (curvature 0, one
  // normal each), which the ghosts' perpendicular-edge images need.
  const double h = 0.0833333;
  const Vec3d o(0.1234567, 0.7654321, 0.3141593);
  auto m = testing::cube_mesh(h, 8);
  for (Vec3d& p : m.v) p = (p + o).cast<float>().cast<double>();
  const TriMeshWall wall(m.v, m.t, TriMeshWall::Side::inside);
  EXPECT_EQ(wall.face_count(), 6);
  std::array<WallPoint<3>, 8> fp;
  const Vec3d x = o + Vec3d(0.9, -0.8, 0.85) * h;  // near the corner (+h, -h, +h)
  const int n = wall.face_points_near(x, 0.3 * h, fp.data(), 8);
  ASSERT_EQ(n, 3);
  for (int k = 0; k < n; ++k) {
    const WallPoint<3>& p = fp[static_cast<std::size_t>(k)];
    EXPECT_EQ(p.k1, 0.0);
    EXPECT_EQ(p.k2, 0.0);
    EXPECT_NEAR(p.normal.cwiseAbs().maxCoeff(), 1.0, 1e-6);                     // an axis
    EXPECT_LT((x - p.foot - p.distance * p.normal).norm(), 1e-6 * p.distance);  // projects
  }
}

TEST(TriMeshFaces, SmoothMeshIsOneFaceAndLeavesClosestToAnswer) {
  // A sphere at 10-degree facets (edges turn by 10 degrees < the 30-degree feature angle).
  const auto m = testing::uv_sphere(0.3, 10.0);
  const TriMeshWall wall(m.v, m.t, TriMeshWall::Side::inside);
  EXPECT_EQ(wall.face_count(), 1);
  std::array<WallPoint<3>, 4> fp;
  EXPECT_EQ(wall.face_points_near(Vec3d(0.25, 0.0, 0.05), 0.2, fp.data(), 4), 0);
}

// Water at rest in the cad_at_rest study's box (0.08 x 0.08 x 0.16 m, H/dx = 6), mirror
// ghosts, 0.05 s: the STL box of 12 triangles against the `box` wall. Before the faces, the
// STL box mirrored across its one closest point only and lost the edges' double images: 0.5 s
// of this case gave 0.334 deep, 85 845 wall contacts and KE 4.1e-2 M g H where the box gives
// 0.043, 0 and 4.7e-6.
TEST(TriMeshFaces, StlBoxTankAtRestIsTheBoxWalls) {
  const auto dir =
      std::filesystem::temp_directory_path() / fmt::format("curvsph_stl_faces_{}", ::getpid());
  std::filesystem::create_directories(dir);
  testing::TestMesh m;
  const Vec3d c(0.04, 0.04, 0.08);
  // The box's 6 faces, 2 triangles each, turned outwards from the centre c.
  for (int a = 0; a < 3; ++a)
    for (double s : {0.0, 1.0}) {
      const int b = (a + 1) % 3, e = (a + 2) % 3;
      const Vec3d L(0.08, 0.08, 0.16);
      auto P = [&](double i, double j) {
        Vec3d p;
        p[a] = s * L[a];
        p[b] = i * L[b];
        p[e] = j * L[e];
        return p;
      };
      m.add(P(0, 0), P(1, 0), P(1, 1), c);
      m.add(P(0, 0), P(1, 1), P(0, 1), c);
    }
  testing::write_ascii_stl((dir / "box.stl").string(), m);
  auto run = [&](const std::string& walls) {
    YAML::Node root = YAML::Load(fmt::format(
        "{{name: stl_box, dimension: 3, resolution: {{dx: {:.12g}, h_over_dx: 2}}, "
        "fluids: [{{name: water, rho0: 1000, viscosity: 1.0e-3, region: {{box: {{min: [0, 0, 0], "
        "max: [0.08, 0.08, 0.08]}}}}}}], initial: {{hydrostatic: {{depth: 0.08, bottom: 0}}}}, "
        "eos: {{type: linear, c0: 8.85889, p0: 0}}, density: {{method: continuity, delta_sph: "
        "0.1}}, gravity: [0, 0, -9.81], boundary: {{method: ghost, map: mirror}}, "
        "time: {{end: 0.05, cfl: 0.25}}, output: {{every: 0.05, vtk: false}}, "
        "analysis: {{hydrostatic: {{depth: 0.08, bottom: 0}}}}}}",
        0.08 / 6));
    root["walls"] = YAML::Load(walls);
    return test::run_quiet(read_case(root, (dir / "stl_box.yaml").string()), 1);
  };
  const auto stl =
      run(fmt::format("[{{shape: cad, file: '{}', fluid: inside}}]", (dir / "box.stl").string()));
  const auto box = run("[{shape: box, min: [0, 0, 0], max: [0.08, 0.08, 0.16], fluid: inside}]");
  std::filesystem::remove_all(dir);
  const double p_stl = stl["pressure_l2_error"].get<double>();
  const double p_box = box["pressure_l2_error"].get<double>();
  std::printf("STL box: p error %.6g, wall contacts %ld, KE max %.3g; box wall: %.6g, %ld, %.3g\n",
              p_stl, stl["wall_contacts"].get<long>(), stl["kinetic_energy_max"].get<double>(),
              p_box, box["wall_contacts"].get<long>(), box["kinetic_energy_max"].get<double>());
  EXPECT_NEAR(p_stl, p_box, 1e-6 * p_box);
  EXPECT_EQ(stl["wall_contacts"].get<long>(), box["wall_contacts"].get<long>());
  EXPECT_EQ(stl["particles_projected"].get<long>(), 0);
}

}  // namespace
}  // namespace curvsph
