// The U-bend pipe of data/cad: two cylinders, a torus, two planes.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <filesystem>
#include <iostream>

#include "curvsph/cad/cad_import.hpp"
#include "curvsph/cad/cad_solid_wall.hpp"
#include "curvsph_build_paths.hpp"

using namespace curvsph;

namespace {
const std::string kDir = CURVSPH_SOURCE_DIR "/data/cad";
}

TEST(CadUPipe, ImportsAndAnswersRadiusOnAxis) {
  if (!std::filesystem::exists(kDir + "/u_pipe.step")) GTEST_SKIP() << "no u_pipe.step";
  const TopoDS_Shape shape = cad::read_brep(kDir + "/u_pipe.step", "case.yaml", "walls.0.file");
  std::cout << "u_pipe.step: " << cad::describe_shape(shape) << "\n";
  const auto walls = make_cad_walls(YAML::Load("{shape: cad, file: u_pipe.step, fluid: inside}"),
                                    "case.yaml", "walls.0", kDir);
  // A closed solid: one wall whose 5 faces answer (cad_solid_wall.hpp).
  ASSERT_EQ(walls.size(), 1u);
  const auto* solid = dynamic_cast<const cad::CadSolidWall*>(walls[0].get());
  ASSERT_NE(solid, nullptr);
  const auto& faces = solid->faces();
  ASSERT_EQ(faces.size(), 5u);
  WallSet<3> set;
  set.add(walls[0]);
  int cylinders = 0;
  int index = 0;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next(), ++index) {
    BRepAdaptor_Surface ad(TopoDS::Face(ex.Current()));
    std::cout << "  " << faces[index]->describe()
              << " min radius of curvature=" << faces[index]->min_radius_of_curvature() << "\n";
    if (ad.GetType() == GeomAbs_Torus) {
      const gp_Torus t = ad.Torus();
      std::cout << "    torus R=" << t.MajorRadius() << " a=" << t.MinorRadius() << "\n";
    }
    if (ad.GetType() != GeomAbs_Cylinder) continue;
    ++cylinders;
    const gp_Cylinder c = ad.Cylinder();
    const double R = c.Radius();
    // A point on the axis, half way along the face.
    const double vm = 0.5 * (ad.FirstVParameter() + ad.LastVParameter());
    const gp_Pnt o = c.Location().Translated(gp_Vec(c.Axis().Direction()) * vm);
    const Vec3d x(o.X(), o.Y(), o.Z());
    const WallPoint<3> p = faces[index]->closest(x);
    const WallPoint<3> q = set.closest(x);
    std::cout << "    cylinder R=" << R << " axis point " << x.transpose() << ": distance "
              << p.distance << " k1=" << p.k1 << " k2=" << p.k2 << " (set: wall " << q.wall
              << ", distance " << q.distance << ")\n";
    EXPECT_NEAR(p.distance, R, 1e-7 * R);  // fluid inside: positive on the axis
    EXPECT_NEAR(q.distance, R, 1e-7 * R);
    EXPECT_NEAR(p.k1, 1.0 / R, 1e-6 / R);  // concave seen from the fluid
    EXPECT_NEAR(p.k2, 0.0, 1e-6 / R);
    EXPECT_LT((p.foot + p.distance * p.normal - x).norm(), 1e-7 * R);
  }
  EXPECT_EQ(cylinders, 2);
}
