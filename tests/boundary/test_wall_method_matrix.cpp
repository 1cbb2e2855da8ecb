// Every wall type with every boundary method (issue 32, "Done when"; the table of
// docs/geometry.md): water at rest under gravity in a small container made of that wall type,
// held for a short time with each ghost map and with boundary integrals. Reference: the
// hydrostatic field rho0 g (H - z) of the run's own analysis, RMS over the particles at least
// one support below the surface ("deep"). Coarse (H/dx = 5 to 10) and short (2-D 0.2 s, 3-D
// 0.05 s), one thread, each from the fill lattice packed inside the walls and the free surface
// (setup.relax with free_faces: hold, 50 steps; the integrals with the node-density packing of
// mirror_beta ghosts, as the cad_at_rest study does). The polygon (degree-1 NURBS) tanks with
// corners of 60, 90 and 120 degrees are test_corner_tank.cpp.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <UnitsMethods.hxx>
#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "../support/quiet_run.hpp"
#include "../support/step_file.hpp"
#include "../support/test_meshes.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / fmt::format("curvsph_matrix_{}", ::getpid());
  fs::create_directories(d);
  return d;
}

using curvsph::test::write_step;

struct Container {
  int dim;
  double dx, depth, bottom;
  std::string region, walls, domain;  // domain: "" or the domain block
};

// The containers, water from `bottom` to bottom + depth.
Container setup(const std::string& wall) {
  if (wall == "plane_2d")
    return {2,
            0.02,
            0.2,
            0,
            "{box: {min: [0, 0], max: [0.4, 0.2]}}",
            "[{shape: plane, point: [0, 0], normal: [0, 1]}, {shape: plane, point: [0, 0], "
            "normal: [1, 0]}, {shape: plane, point: [0.4, 0], normal: [-1, 0]}]",
            "{min: [-0.1, -0.1], max: [0.5, 0.4]}"};
  if (wall == "box_2d")
    return {2,
            0.02,
            0.2,
            0,
            "{box: {min: [0, 0], max: [0.4, 0.2]}}",
            "[{shape: box, min: [0, 0], max: [0.4, 0.4], fluid: inside}]",
            ""};
  if (wall == "circle")
    return {2,
            0.02,
            0.2,
            -0.2,
            "{box: {min: [-0.2, -0.2], max: [0.2, 0]}}",
            "[{shape: circle, center: [0, 0], radius: 0.2, fluid: inside}]",
            ""};
  if (wall == "ellipse")
    return {2,
            0.02,
            0.2,
            -0.2,
            "{box: {min: [-0.3, -0.2], max: [0.3, 0]}}",
            "[{shape: ellipse, center: [0, 0], semi_axes: [0.3, 0.2], fluid: inside}]",
            ""};
  if (wall == "nurbs_circle") {
    // The exact circle of radius 0.2: 9 control points, weights sqrt(2)/2 at the corners,
    // counter-clockwise (fluid on the left: inside).
    const double r = 0.2, w = std::sqrt(0.5);
    return {2,
            0.02,
            0.2,
            -0.2,
            "{box: {min: [-0.2, -0.2], max: [0.2, 0]}}",
            fmt::format("[{{shape: nurbs_curve, degree: 2, fluid: left, "
                        "knots: [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4], "
                        "weights: [1, {w}, 1, {w}, 1, {w}, 1, {w}, 1], "
                        "control_points: [[{r}, 0], [{r}, {r}], [0, {r}], [-{r}, {r}], [-{r}, 0], "
                        "[-{r}, -{r}], [0, -{r}], [{r}, -{r}], [{r}, 0]]}}]",
                        fmt::arg("r", r), fmt::arg("w", w)),
            ""};
  }
  if (wall == "plane_3d")
    return {3,
            0.02,
            0.1,
            0,
            "{box: {min: [0, 0, 0], max: [0.24, 0.24, 0.1]}}",
            "[{shape: plane, point: [0, 0, 0], normal: [0, 0, 1]}]",
            "{min: [0, 0, -0.1], max: [0.24, 0.24, 0.3], periodic: [true, true, false]}"};
  if (wall == "box_3d")
    return {3,
            0.02,
            0.1,
            0,
            "{box: {min: [0, 0, 0], max: [0.12, 0.12, 0.1]}}",
            "[{shape: box, min: [0, 0, 0], max: [0.12, 0.12, 0.2], fluid: inside}]",
            ""};
  // The curved 3-D walls at H/dx = 8 (R = 8 dx): at H/dx = 5 the one row at least 2h below
  // the surface lies along the wall, and the packed sphere gave 0.034 to 0.21 at 0.05 s, above
  // 5 % with three methods of four (docs/geometry.md).
  if (wall == "cylinder")
    // Periodic over 0.16 = 3.2 supports (the cell list needs 3).
    return {3,
            0.0125,
            0.1,
            -0.1,
            "{box: {min: [0, -0.1, -0.1], max: [0.16, 0.1, 0]}}",
            "[{shape: cylinder, point: [0, 0, 0], axis: [1, 0, 0], radius: 0.1, fluid: inside}]",
            "{min: [0, -0.2, -0.2], max: [0.16, 0.2, 0.2], periodic: [true, false, false]}"};
  if (wall == "sphere")
    return {3,
            0.0125,
            0.1,
            -0.1,
            "{box: {min: [-0.1, -0.1, -0.1], max: [0.1, 0.1, 0]}}",
            "[{shape: sphere, center: [0, 0, 0], radius: 0.1, fluid: inside}]",
            ""};
  if (wall == "torus")
    // dx = 0.01125 (H/dx = 6.7): 2h = 0.045 below the tube radius 0.075 (a concave radius
    // below 2h is refused at set-up, check_concave_support). Major radius 0.15: at 0.125 the
    // density-preserving map's depth limit at the inner equator (radius of curvature R - a =
    // 0.05) is refused at this h.
    return {3,
            0.01125,
            0.075,
            -0.075,
            "{box: {min: [-0.25, -0.25, -0.075], max: [0.25, 0.25, 0]}}",
            "[{shape: torus, center: [0, 0, 0], axis: [0, 0, 1], major_radius: 0.15, "
            "minor_radius: 0.075, fluid: inside}]",
            ""};
  if (wall == "nurbs_surface")
    // A flat degree-1 patch reaching well beyond the periodic cell: the floor.
    return {3,
            0.02,
            0.1,
            0,
            "{box: {min: [0, 0, 0], max: [0.24, 0.24, 0.1]}}",
            "[{shape: nurbs_surface, degree: [1, 1], fluid: front, knots_u: [0, 0, 1, 1], "
            "knots_v: [0, 0, 1, 1], control_points: [[[-0.3, -0.3, 0], [-0.3, 0.5, 0]], "
            "[[0.5, -0.3, 0], [0.5, 0.5, 0]]]}]",
            "{min: [0, 0, -0.1], max: [0.24, 0.24, 0.3], periodic: [true, true, false]}"};
  const fs::path dir = scratch();
  if (wall == "cad_box") {
    write_step(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(0.12, 0.12, 0.2)).Shape(),
               dir / "box.step");
    return {3,
            0.02,
            0.1,
            0,
            "{box: {min: [0, 0, 0], max: [0.12, 0.12, 0.1]}}",
            fmt::format("[{{shape: cad, file: '{}', fluid: inside}}]", (dir / "box.step").string()),
            ""};
  }
  if (wall == "cad_cylinder") {
    // H/dx = 5: each CAD closest point costs ~0.25 ms, and at H/dx = 8 one cell took 78 s
    // (packing and run). Radius 0.1 > 2h: at 0.07 (< 2h) mirror_beta's beta = (1 + d/R)/(1 - d/R)
    // grows without bound for the particles near the axis, each of which mirrors across the side
    // too; the run blew up (kinetic energy 52 M g H at 0.05 s, one particle put back).
    write_step(BRepPrimAPI_MakeCylinder(0.1, 0.2).Shape(), dir / "cylinder.step");
    return {3,
            0.02,
            0.1,
            0,
            "{box: {min: [-0.1, -0.1, 0], max: [0.1, 0.1, 0.1]}}",
            fmt::format("[{{shape: cad, file: '{}', fluid: inside}}]",
                        (dir / "cylinder.step").string()),
            ""};
  }
  if (wall == "stl_box") {
    // H/dx = 6: at H/dx = 4 no particle lies 2h below the surface.
    testing::write_ascii_stl((dir / "cube.stl").string(), testing::cube_mesh(0.08, 4));
    return {3,
            0.08 / 6,
            0.08,
            -0.08,
            "{box: {min: [-0.08, -0.08, -0.08], max: [0.08, 0.08, 0]}}",
            fmt::format("[{{shape: cad, file: '{}', fluid: inside}}]", (dir / "cube.stl").string()),
            ""};
  }
  if (wall == "stl_sphere") {
    // 1280 triangles, edges of about 8 degrees (1.1 dx). With 180 (21 degrees, 3 dx) the
    // integrals missed (0.068, the row along the wall): packed with mirror_beta ghosts on the
    // mesh's smoothed curvature, off the balance of the integrals, which see flat facets.
    testing::write_ascii_stl((dir / "ball.stl").string(), testing::icosphere(0.1, 8));
    return {3,
            0.0125,
            0.1,
            -0.1,
            "{box: {min: [-0.1, -0.1, -0.1], max: [0.1, 0.1, 0]}}",
            fmt::format("[{{shape: cad, file: '{}', fluid: inside}}]", (dir / "ball.stl").string()),
            ""};
  }
  ADD_FAILURE() << "unknown wall " << wall;
  return {};
}

YAML::Node make_case(const Container& s, const std::string& method) {
  const std::string boundary = method == "integrals" ? std::string("{method: integrals}")
                                                     : "{method: ghost, map: " + method + "}";
  const double t_end = s.dim == 2 ? 0.2 : 0.05;
  YAML::Node root = YAML::Load(fmt::format(
      "{{name: matrix, dimension: {}, resolution: {{dx: {}, h_over_dx: 2}}, "
      "fluids: [{{name: water, rho0: 1000, viscosity: 1.0e-3, region: {}}}], "
      "initial: {{hydrostatic: {{depth: {}, bottom: {}}}}}, "
      "eos: {{type: linear, c0: {:.6g}, p0: 0}}, density: {{method: continuity, delta_sph: 0.1}}, "
      "gravity: {}, boundary: {}, time: {{end: {}, cfl: 0.25}}, "
      "output: {{every: {}, vtk: false}}, analysis: {{hydrostatic: {{depth: {}, bottom: {}}}}}}}",
      s.dim, s.dx, s.region, s.depth, s.bottom, 10 * std::sqrt(9.81 * s.depth),
      s.dim == 2 ? "[0, -9.81]" : "[0, 0, -9.81]", boundary, t_end, t_end / 2, s.depth, s.bottom));
  root["walls"] = YAML::Load(s.walls);
  if (!s.domain.empty()) root["domain"] = YAML::Load(s.domain);
  // Packed first: on the bare lattice a wall across it (curved) leaves the first rows off
  // equilibrium, the integrals' too (circle 0.24 to 0.26 with ghosts and 0.068 with integrals,
  // sphere at R = 5 dx 0.18 to 1.24, at the same times; docs/geometry.md). 50 steps do as
  // well as 200 here (circle 0.010 to 0.018 either way); the integrals take the default
  // packing map, boundary.map = mirror_beta (their own packing closes a box region only).
  root["setup"] = YAML::Load("{relax: {free_faces: hold, max_steps: 50}}");
  return root;
}

class WallMethod : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(WallMethod, HoldsWaterAtRest) {
  const auto [wall, method] = GetParam();
  Container s = setup(wall);
  // The plain mirror in the faceted sphere runs at R = 10 dx: it miscounts the ghosts' volume
  // at a concave wall (Barker: an error of order dx / R, which mirror_beta's volume factor
  // corrects), and its packing does not converge there (node-density spread 0.025 after 50
  // and 400 steps at R = 8 dx). Measured with this test's case at 0.05 s (deep): R = 8, 10,
  // 12, 16 dx: 0.0547, 0.0253, 0.0170, 0.0109 (the analytic sphere 0.0459, 0.0251, 0.0159,
  // 0.0104; the periodic cylinder 0.0223, 0.0189, 0.0070, 0.0047); docs/geometry.md, note (f).
  const bool mirror_in_mesh_sphere = wall == "stl_sphere" && method == "mirror";
  if (mirror_in_mesh_sphere) s.dx = 0.01;
  const auto m = test::run_quiet(read_case(make_case(s, method), "matrix.yaml"), 1);
  const double t_end = s.dim == 2 ? 0.2 : 0.05;
  std::cout << fmt::format(
      "matrix {} {}: particles {} projected {} contacts {} escaped {} p_deep {:.4f} p_all {:.4f} "
      "ke_max {:.2e} relax_spread {:.3g}\n",
      wall, method, m["particles"].get<long>(), m["particles_projected"].get<long>(),
      m["wall_contacts"].get<long>(), m["escaped_particles"].get<long>(),
      m["pressure_l2_error_deep"].is_number() ? m["pressure_l2_error_deep"].get<double>() : -1.0,
      m["pressure_l2_error"].get<double>(), m["kinetic_energy_max"].get<double>(),
      m.value("relax_node_density_spread", -1.0));
  EXPECT_NEAR(m["time_reached"].get<double>(), t_end, 1e-9);
  EXPECT_EQ(m["particles_projected"].get<long>(), 0);
  EXPECT_EQ(m["escaped_particles"].get<long>(), 0);
  EXPECT_EQ(m["particles_removed"].get<long>(), 0);
  // The hydrostatic pressure within 5 % of rho g H: the cells marked "works" in
  // docs/geometry.md, every cell. Integrals on the three `plane` walls: 0.0086 (0.0635 while
  // each infinite plane's boundary elements were clipped to the domain box only and ran on
  // behind the other planes, the two floor-corner particles at -0.47 rho g H each; now each
  // is clipped by the others, boundary/integrals/wall_clip.hpp).
  ASSERT_TRUE(m["pressure_l2_error_deep"].is_number()) << "no particle 2h below the surface";
  EXPECT_LT(m["pressure_l2_error_deep"].get<double>(), 0.05);
}

// The `plane` tank with integrals, its domain box ending at the side walls and the floor, so
// that each plane's elements end where the planes meet without the clipping by the other walls:
// the same figure as the clipped elements in the larger box above (0.0088).
TEST(WallMethodMatrix, PlaneWallsEndingAtTheCorner) {
  Container s = setup("plane_2d");
  s.domain = "{min: [0, 0], max: [0.4, 0.4]}";
  const auto m = test::run_quiet(read_case(make_case(s, "integrals"), "matrix.yaml"), 1);
  EXPECT_EQ(m["particles_projected"].get<long>(), 0);
  EXPECT_EQ(m["escaped_particles"].get<long>(), 0);
  EXPECT_LT(m["pressure_l2_error_deep"].get<double>(), 0.05);
}

const std::vector<std::string> kMethods = {"mirror", "mirror_beta", "density_preserving",
                                           "integrals"};

INSTANTIATE_TEST_SUITE_P(
    Walls2D, WallMethod,
    ::testing::Combine(::testing::Values("plane_2d", "box_2d", "circle", "ellipse", "nurbs_circle"),
                       ::testing::ValuesIn(kMethods)),
    [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });

INSTANTIATE_TEST_SUITE_P(
    Walls3D, WallMethod,
    ::testing::Combine(::testing::Values("plane_3d", "box_3d", "cylinder", "sphere", "torus",
                                         "nurbs_surface", "cad_box", "cad_cylinder", "stl_box",
                                         "stl_sphere"),
                       ::testing::ValuesIn(kMethods)),
    [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });

}  // namespace
}  // namespace curvsph
