// Planar and cylindrical CAD faces answer the closest point in closed form
// (cad/elementary_face.hpp); reference: the general path of the same face, the projection on
// its NURBS conversion with the same trimming (TrimmedFaceWall::closest_nurbs), whose accuracy
// against the analytic solids is tests/cad/test_cad_solid_wall.cpp's.
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
#include <iostream>
#include <random>

#include "../support/step_file.hpp"
#include "curvsph/cad/cad_solid_wall.hpp"
#include "curvsph/geometry/wall_parser.hpp"

using namespace curvsph;

namespace {

using curvsph::test::write_step;

TEST(ElementaryFace, PlanesAndCylindersAnswerAsTheirNurbs) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("curvsph_elementary_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const double R = 0.06, H = 0.16;
  write_step(BRepPrimAPI_MakeCylinder(R, H).Shape(), dir / "cylinder.step");
  write_step(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(0.08, 0.08, H)).Shape(), dir / "box.step");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.03, 0.11), c(-0.09, 0.09), z(-0.03, 0.19);
  for (const std::string solid : {"cylinder", "box"})
    for (const std::string fluid : {"inside", "outside"}) {
      const WallSet<3> walls = parse_walls<3>(
          YAML::Load("[{shape: cad, file: " + solid + ".step, fluid: " + fluid + "}]"),
          (dir / "case.yaml").string(), dir);
      const auto* s = dynamic_cast<const cad::CadSolidWall*>(&walls[0]);
      ASSERT_NE(s, nullptr);
      double worst_d = 0, worst_f = 0, worst_n = 0, worst_k = 0;
      int trimmed = 0;
      for (int i = 0; i < 300; ++i) {
        const Vec3d x =
            solid == "box" ? Vec3d(u(rng), u(rng), z(rng)) : Vec3d(c(rng), c(rng), z(rng));
        for (const auto& f : s->faces()) {
          const WallPoint<3> a = f->closest(x), b = f->closest_nurbs(x);
          worst_d = std::max(worst_d, std::abs(a.distance - b.distance));
          worst_f = std::max(worst_f, (a.foot - b.foot).norm());
          worst_n = std::max(worst_n, (a.normal - b.normal).norm());
          worst_k = std::max({worst_k, std::abs(a.k1 - b.k1), std::abs(a.k2 - b.k2)});
          trimmed += (x - a.foot).cross(a.normal).norm() > 1e-9;  // foot on the face's boundary
        }
      }
      std::cout << solid << ", fluid " << fluid << ": max |d| " << worst_d << ", |foot| " << worst_f
                << ", |n| " << worst_n << ", |k| " << worst_k << " (" << trimmed
                << " feet on a boundary)\n";
      EXPECT_LT(worst_d, 1e-9);
      EXPECT_LT(worst_f, 1e-9);
      EXPECT_LT(worst_n, 1e-7);
      EXPECT_LT(worst_k, 1e-6 / R);
      EXPECT_GT(trimmed, 100);
    }
  std::filesystem::remove_all(dir);
}

}  // namespace
