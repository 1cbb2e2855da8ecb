// STEP / IGES written by OpenCASCADE read back to the same control net, units to metres,
// and NURBS evaluation / curvature / projection against OpenCASCADE as an oracle.
#include <gtest/gtest.h>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomLProp_CLProps.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <UnitsMethods.hxx>
#include <filesystem>
#include <random>

#include "../nurbs/test_shapes.hpp"
#include "curvsph/cad/cad_import.hpp"
#include "curvsph/cad/trimmed_face_wall.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/nurbs/projection.hpp"

using namespace curvsph;

namespace {

void to_occ_knots(const std::vector<double>& flat, TColStd_Array1OfReal*& k,
                  TColStd_Array1OfInteger*& m) {
  std::vector<double> u;
  std::vector<int> mult;
  for (double v : flat) {
    if (!u.empty() && u.back() == v) {
      ++mult.back();
    } else {
      u.push_back(v);
      mult.push_back(1);
    }
  }
  k = new TColStd_Array1OfReal(1, static_cast<int>(u.size()));
  m = new TColStd_Array1OfInteger(1, static_cast<int>(u.size()));
  for (std::size_t i = 0; i < u.size(); ++i) {
    (*k)(static_cast<int>(i) + 1) = u[i];
    (*m)(static_cast<int>(i) + 1) = mult[i];
  }
}

Handle(Geom_BSplineSurface) to_occ(const nurbs::NurbsSurface& s) {
  TColgp_Array2OfPnt P(1, s.count_u(), 1, s.count_v());
  TColStd_Array2OfReal W(1, s.count_u(), 1, s.count_v());
  for (int i = 0; i < s.count_u(); ++i)
    for (int j = 0; j < s.count_v(); ++j) {
      const Vec3d c = s.control_point(i, j);
      P(i + 1, j + 1) = gp_Pnt(c.x(), c.y(), c.z());
      W(i + 1, j + 1) = s.weight(i, j);
    }
  TColStd_Array1OfReal *ku, *kv;
  TColStd_Array1OfInteger *mu, *mv;
  to_occ_knots(s.knots_u(), ku, mu);
  to_occ_knots(s.knots_v(), kv, mv);
  Handle(Geom_BSplineSurface) b =
      new Geom_BSplineSurface(P, W, *ku, *kv, *mu, *mv, s.degree_u(), s.degree_v());
  delete ku, delete kv, delete mu, delete mv;
  return b;
}

Handle(Geom_BSplineCurve) to_occ(const nurbs::NurbsCurve<3>& c) {
  TColgp_Array1OfPnt P(1, static_cast<int>(c.control_points().size()));
  TColStd_Array1OfReal W(1, P.Length());
  for (int i = 0; i < P.Length(); ++i) {
    const Vec3d& p = c.control_points()[i];
    P(i + 1) = gp_Pnt(p.x(), p.y(), p.z());
    W(i + 1) = c.weights()[i];
  }
  TColStd_Array1OfReal* k;
  TColStd_Array1OfInteger* m;
  to_occ_knots(c.knots(), k, m);
  Handle(Geom_BSplineCurve) b = new Geom_BSplineCurve(P, W, *k, *m, c.degree());
  delete k, delete m;
  return b;
}

std::filesystem::path temp_dir() {
  auto d = std::filesystem::temp_directory_path() / "curvsph_cad_test";
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace

TEST(CadOracle, CurveEvaluationCurvatureAndProjectionMatchOpenCascade) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const auto c = test::random_curve<3>(seed, 1 + seed, 9);
    const Handle(Geom_BSplineCurve) oc = to_occ(c);
    const nurbs::CurveProjector<3> pr(c);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> T(0.0, 1.0), X(-1.0, 1.0);
    for (int k = 0; k < 200; ++k) {
      const double t = T(rng);
      const auto d = c.eval(t);
      gp_Pnt p;
      gp_Vec v1, v2;
      oc->D2(t, p, v1, v2);
      EXPECT_LT((d.c - Vec3d(p.X(), p.Y(), p.Z())).norm(), 1e-12);
      EXPECT_LT((d.d1 - Vec3d(v1.X(), v1.Y(), v1.Z())).norm(), 1e-9 * (1 + d.d1.norm()));
      EXPECT_LT((d.d2 - Vec3d(v2.X(), v2.Y(), v2.Z())).norm(), 1e-8 * (1 + d.d2.norm()));
      GeomLProp_CLProps props(oc, t, 2, 1e-12);
      EXPECT_NEAR(nurbs::curvature(d), props.Curvature(), 1e-8 * (1 + props.Curvature()));
      // Projection: never farther than OpenCASCADE's nearest orthogonal projection.
      const Vec3d x = d.c + 0.3 * Vec3d(X(rng), X(rng), X(rng));
      GeomAPI_ProjectPointOnCurve occ(gp_Pnt(x.x(), x.y(), x.z()), oc);
      const nurbs::Projection r = pr.project(x, nullptr);
      if (occ.NbPoints() > 0) {
        EXPECT_LE(r.distance, occ.LowerDistance() + 1e-9);
      }
    }
  }
}

TEST(CadOracle, SurfaceEvaluationCurvatureAndProjectionMatchOpenCascade) {
  const auto s = test::random_surface(8, 3, 2, 6, 5);
  const Handle(Geom_BSplineSurface) os = to_occ(s);
  const nurbs::SurfaceProjector pr(s);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> T(0.0, 1.0), X(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const double u = T(rng), v = T(rng);
    const auto d = s.eval(u, v);
    gp_Pnt p;
    gp_Vec su, sv, suu, svv, suv;
    os->D2(u, v, p, su, sv, suu, svv, suv);
    const auto V = [](const gp_Vec& g) { return Vec3d(g.X(), g.Y(), g.Z()); };
    EXPECT_LT((d.s - Vec3d(p.X(), p.Y(), p.Z())).norm(), 1e-12);
    EXPECT_LT((d.su - V(su)).norm(), 1e-9 * (1 + d.su.norm()));
    EXPECT_LT((d.suv - V(suv)).norm(), 1e-8 * (1 + d.suv.norm()));
    EXPECT_LT((d.svv - V(svv)).norm(), 1e-8 * (1 + d.svv.norm()));
    GeomLProp_SLProps props(os, u, v, 2, 1e-12);
    ASSERT_TRUE(props.IsCurvatureDefined());
    const Vec3d n = d.su.cross(d.sv).normalized();
    const auto pc = nurbs::principal_curvatures(d, n);
    // OCCT's curvatures are relative to its normal Su x Sv as well.
    const double kmax = props.MaxCurvature(), kmin = props.MinCurvature();
    EXPECT_NEAR(pc.k1, std::max(kmax, kmin), 1e-7 * (1 + std::abs(kmax)));
    EXPECT_NEAR(pc.k2, std::min(kmax, kmin), 1e-7 * (1 + std::abs(kmin)));
    const Vec3d x = d.s + 0.5 * Vec3d(X(rng), X(rng), X(rng));
    GeomAPI_ProjectPointOnSurf occ(gp_Pnt(x.x(), x.y(), x.z()), os);
    const nurbs::Projection r = pr.project(x, nullptr);
    if (occ.NbPoints() > 0) {
      EXPECT_LE(r.distance, occ.LowerDistance() + 1e-9);
    }
  }
}

TEST(CadRoundTrip, StepAndIgesReadBackToTheSameControlNet) {
  const auto s = test::random_surface(5, 3, 2, 5, 4);
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(to_occ(s), 1e-7);
  const auto dir = temp_dir();
  // The writers take the session unit when they are made: set it first.
  STEPControl_Controller::Init();
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  Interface_Static::SetCVal("write.step.unit", "M");
  UnitsMethods::SetCasCadeLengthUnit(1000.0);  // session unit = 1000 mm
  STEPControl_Writer sw;
  ASSERT_EQ(sw.Transfer(face, STEPControl_AsIs), IFSelect_RetDone);
  ASSERT_EQ(sw.Write((dir / "patch.step").c_str()), IFSelect_RetDone);
  // OCCT 7.6's IGES writer takes shapes as millimetres whatever the session unit: the IGES
  // file is then a millimetre file and must read back scaled by 1e-3.
  IGESControl_Controller::Init();
  IGESControl_Writer iw("MM", 1);
  iw.AddShape(face);
  iw.ComputeModel();
  ASSERT_TRUE(iw.Write((dir / "patch.iges").c_str()));
  for (const char* name : {"patch.step", "patch.iges"}) {
    const double unit = std::string(name) == "patch.iges" ? 1e-3 : 1.0;
    const auto walls =
        make_cad_walls(YAML::Load(std::string("{shape: cad, fluid: outside, file: ") + name + "}"),
                       "case.yaml", "walls.0", dir.string());
    ASSERT_EQ(walls.size(), 1u) << name;
    const auto* tw = dynamic_cast<const cad::TrimmedFaceWall*>(walls[0].get());
    ASSERT_NE(tw, nullptr);
    const nurbs::NurbsSurface& r = tw->surface_wall().surface();
    ASSERT_EQ(r.count_u(), s.count_u()) << name;
    ASSERT_EQ(r.count_v(), s.count_v()) << name;
    for (int i = 0; i < s.count_u(); ++i)
      for (int j = 0; j < s.count_v(); ++j) {
        EXPECT_LT((r.control_point(i, j) - unit * s.control_point(i, j)).norm(), 1e-9 * unit)
            << name;
        EXPECT_NEAR(r.weight(i, j) / r.weight(0, 0), s.weight(i, j) / s.weight(0, 0), 1e-9);
      }
  }
}

TEST(CadRoundTrip, StepInMillimetresReadsBackInMetres) {
  const auto dir = temp_dir();
  STEPControl_Controller::Init();
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");  // the shape is in mm
  Interface_Static::SetCVal("write.step.unit", "MM");
  UnitsMethods::SetCasCadeLengthUnit(1.0);
  STEPControl_Writer sw;
  ASSERT_EQ(sw.Transfer(BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape(), STEPControl_AsIs),
            IFSelect_RetDone);
  ASSERT_EQ(sw.Write((dir / "box_mm.step").c_str()), IFSelect_RetDone);
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  const TopoDS_Shape shape = cad::read_brep((dir / "box_mm.step").string(), "case.yaml", "file");
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, false, false);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  EXPECT_NEAR(x1 - x0, 0.010, 1e-9);
  EXPECT_NEAR(y1 - y0, 0.020, 1e-9);
  EXPECT_NEAR(z1 - z0, 0.030, 1e-9);
  // A box with the fluid inside (a closed solid: one wall): the centre is 5 mm from the nearest
  // face, on the fluid side; a point beyond a face's trimmed extent lands on that face's edge.
  const auto walls = make_cad_walls(YAML::Load("{shape: cad, file: box_mm.step, fluid: inside}"),
                                    "case.yaml", "walls.0", dir.string());
  ASSERT_EQ(walls.size(), 1u);  // a closed box: one wall of 6 faces (cad_solid_wall.hpp)
  WallSet<3> set;
  for (const auto& w : walls) set.add(w);
  const WallPoint<3> c = set.closest(Vec3d(0.005, 0.010, 0.015));
  EXPECT_NEAR(c.distance, 0.005, 1e-12);
  const WallPoint<3> out = set.closest(Vec3d(0.012, 0.010, 0.032));  // outside, past a corner edge
  EXPECT_NEAR(std::abs(out.distance), std::hypot(0.002, 0.002), 1e-9);
  EXPECT_LT(out.distance, 0.0);
  EXPECT_LT((out.foot - Vec3d(0.010, 0.010, 0.030)).norm(), 1e-9);
}

TEST(CadInput, ErrorsNameTheKey) {
  const auto key = [](const char* yaml) {
    try {
      make_cad_walls(YAML::Load(yaml), "case.yaml", "walls.3", "/nonexistent");
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("<no error>");
  };
  EXPECT_EQ(key("{shape: cad, file: a.step, fluid: inside}"), "walls.3.file");
  EXPECT_EQ(key("{shape: cad, fluid: inside}"), "walls.3.file");
  EXPECT_EQ(key("{shape: cad, file: a.step, fluid: left}"), "walls.3.fluid");
  EXPECT_EQ(key("{shape: cad, file: a.step}"), "walls.3.fluid");
  EXPECT_EQ(key("{shape: cad, file: a.step, fluid: inside, scale: -1}"), "walls.3.scale");
  EXPECT_EQ(key("{shape: cad, file: a.xyz, fluid: inside}"), "walls.3.file");
}
