// Boundary elements of trimmed CAD faces: a closed cylinder built by OpenCASCADE (a lateral
// face with a seam and two planar faces trimmed by circles) turned into walls as a STEP file
// would be, its elements' area against the solid's, and the geometric Shepard factor against
// adaptive quadrature of W over the solid (tests/support/shepard_reference.hpp) at points
// approaching its faces, its seam and its circular edges, fluid inside and outside.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shape.hxx>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gp_Circ.hxx>
#include <numbers>
#include <numeric>
#include <string>

#include "../support/shepard_reference.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/cad/cad_import.hpp"

using namespace curvsph;

TEST(TrimmedFaceElements, CylinderSolidFacesSeamAndRims) {
  constexpr double pi = std::numbers::pi;
  const double R = 1.0, H = 0.6, h = 0.1, dx = 0.05;
  const TopoDS_Shape solid = BRepPrimAPI_MakeCylinder(R, H).Shape();
  double worst = 0;
  for (auto side : {cad::FluidSide::inside, cad::FluidSide::outside}) {
    const bool inside = side == cad::FluidSide::inside;
    WallSet<3> walls;
    for (auto& w : cad::faces_to_walls(solid, side, 1.0)) walls.add(w);
    ASSERT_EQ(walls.size(), 3u);
    const auto el = elements_from_walls<3>(walls, dx, {});
    // The discs' rims are polygons of chords about dx / 4 long: their area is short of
    // pi R^2 by (2 pi / n)^2 / 6 of it, about 2e-5 of the whole here.
    const double area = std::accumulate(el.area.begin(), el.area.end(), 0.0);
    const double exact = 2 * pi * R * H + 2 * pi * R * R;
    EXPECT_NEAR(area / exact, 1.0, 5e-5);
    std::printf("CAD cylinder (%s): %zu elements, area / exact - 1 = %.2e\n",
                inside ? "inside" : "outside", el.size(), area / exact - 1);
    for (std::size_t j = 0; j < el.size(); ++j) {
      const Vec3d c = el.centre[j];
      // Into the fluid: towards the axis / the middle for the fluid inside.
      const Vec3d to_middle = Vec3d(0, 0, 0.5 * H) - c;
      const Vec3d radial(c.x(), c.y(), 0);
      const Vec3d inward = std::abs(c.z()) < 1e-9 || std::abs(c.z() - H) < 1e-9
                               ? Vec3d(0, 0, to_middle.z())
                               : Vec3d(-radial);
      EXPECT_EQ(el.normal[j].dot(inward) > 0, inside) << c.transpose();
    }
    const GeometricShepard<3> fast(el, h);
    std::vector<std::size_t> all(el.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    const test::Columns fluid = [&](double X, double Y) {
      std::vector<std::pair<double, double>> out;
      const bool over = X * X + Y * Y < R * R;
      if (inside && over) out.push_back({0.0, H});
      if (!inside && over) out = {{-1e300, 0.0}, {H, 1e300}};
      if (!inside && !over) out.push_back({-1e300, 1e300});
      return out;
    };
    const double s = inside ? 1.0 : -1.0;
    auto radial = [](double phi) { return Vec3d(std::cos(phi), std::sin(phi), 0); };
    struct Probe {
      const char* what;
      Vec3d base, dir;
    };
    const std::vector<Probe> probes = {
        {"bottom disc", Vec3d(0.1, 0.05, 0), s * Vec3d(0, 0, 1)},
        {"top disc near the rim", Vec3d(0.25, -0.9, H), -s * Vec3d(0, 0, 1)},
        {"lateral face", R * radial(2.0) + Vec3d(0, 0, 0.3), -s * radial(2.0)},
        {"lateral face at the seam", Vec3d(R, 0, 0.3), -s * radial(0.0)},
        {"bottom rim", R * radial(0.7), s * (Vec3d(0, 0, 1) - radial(0.7)).normalized()},
        {"top rim", R * radial(3.0) + Vec3d(0, 0, H),
         -s * (Vec3d(0, 0, 1) + radial(3.0)).normalized()}};
    for (const Probe& pr : probes) {
      double worst_here = 0;
      // A point of a curved rim between its samples lies outside the elements (by the
      // chords' sagitta, (dx / 4)^2 / (8 R) = 2e-5 here): the rims are approached to 1e-3 h.
      const bool rim = std::string(pr.what).find("rim") != std::string::npos;
      for (double d : {1.5, 1.0, 0.5, 0.2, 0.05, 1e-3, 0.0}) {
        if (rim && d == 0.0) continue;
        const Vec3d x = pr.base + d * h * pr.dir;
        const double ref = test::reference_gamma_3d(x, h, fluid);
        const double e = std::max(std::abs(shepard_geometric<3>(el, x, h) - ref),
                                  std::abs(fast(el, all, x) - ref));
        worst_here = std::max(worst_here, e);
        EXPECT_LT(e, 0.005) << pr.what << " inside " << inside << " d/h " << d << " ref " << ref;
      }
      std::printf("CAD cylinder (%s), %s: max |gamma - ref| = %.2e\n",
                  inside ? "inside" : "outside", pr.what, worst_here);
      worst = std::max(worst, worst_here);
    }
  }
  std::printf("CAD cylinder: max |gamma - ref| = %.2e\n", worst);
}

TEST(TrimmedFaceElements, PlateWithAHoleInnerLoops) {
  // A plate [0, L]^2 x [0, H] with a round hole through it (OpenCASCADE: a face with an inner
  // wire, extruded): its top and bottom faces are trimmed by an outer square and an inner
  // circle, so their cells are cut by a hole loop. Fluid inside the plate (the material).
  constexpr double pi = std::numbers::pi;
  const double L = 1.2, H = 0.4, r = 0.4, h = 0.1, dx = 0.05;
  const gp_Pnt c(0.6, 0.6, 0);
  const TopoDS_Wire outer =
      BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(L, 0, 0), gp_Pnt(L, L, 0), gp_Pnt(0, L, 0),
                                 Standard_True)
          .Wire();
  const TopoDS_Wire hole =
      BRepBuilderAPI_MakeWire(
          BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(c, gp_Dir(0, 0, 1)), r)).Edge())
          .Wire();
  BRepBuilderAPI_MakeFace mf(outer);
  mf.Add(TopoDS::Wire(hole.Reversed()));
  const TopoDS_Shape plate = BRepPrimAPI_MakePrism(mf.Face(), gp_Vec(0, 0, H)).Shape();
  WallSet<3> walls;
  for (auto& w : cad::faces_to_walls(plate, cad::FluidSide::inside, 1.0)) walls.add(w);
  ASSERT_EQ(walls.size(), 7u);  // 4 sides, bottom, top, the hole
  const auto el = elements_from_walls<3>(walls, dx, {});
  const double area = std::accumulate(el.area.begin(), el.area.end(), 0.0);
  const double exact = 2 * (L * L - pi * r * r) + 4 * L * H + 2 * pi * r * H;
  EXPECT_NEAR(area / exact, 1.0, 5e-5);
  std::printf("CAD plate with a hole: %zu elements, area / exact - 1 = %.2e\n", el.size(),
              area / exact - 1);
  const GeometricShepard<3> fast(el, h);
  std::vector<std::size_t> all(el.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  const test::Columns fluid = [&](double X, double Y) {
    std::vector<std::pair<double, double>> out;
    const double dxc = X - c.X(), dyc = Y - c.Y();
    if (X > 0 && X < L && Y > 0 && Y < L && dxc * dxc + dyc * dyc > r * r) out.push_back({0.0, H});
    return out;
  };
  auto radial = [](double phi) { return Vec3d(std::cos(phi), std::sin(phi), 0); };
  const Vec3d cc(c.X(), c.Y(), 0);
  struct Probe {
    const char* what;
    Vec3d base, dir;
  };
  const std::vector<Probe> probes = {
      {"top face by the hole", cc + (r + 0.03) * radial(0.4) + Vec3d(0, 0, H), Vec3d(0, 0, -1)},
      {"hole face", cc + r * radial(2.2) + Vec3d(0, 0, 0.5 * H), radial(2.2)},
      {"top rim of the hole", cc + r * radial(4.0) + Vec3d(0, 0, H),
       (radial(4.0) - Vec3d(0, 0, 1)).normalized()},
      {"bottom rim of the hole", cc + r * radial(5.5),
       (radial(5.5) + Vec3d(0, 0, 1)).normalized()}};
  double worst = 0;
  for (const Probe& pr : probes) {
    double worst_here = 0;
    for (double d : {1.5, 1.0, 0.5, 0.2, 0.05, 1e-3}) {
      const Vec3d x = pr.base + d * h * pr.dir;
      const double ref = test::reference_gamma_3d(x, h, fluid);
      const double e = std::max(std::abs(shepard_geometric<3>(el, x, h) - ref),
                                std::abs(fast(el, all, x) - ref));
      worst_here = std::max(worst_here, e);
      EXPECT_LT(e, 0.005) << pr.what << " d/h " << d << " ref " << ref;
    }
    std::printf("CAD plate with a hole, %s: max |gamma - ref| = %.2e\n", pr.what, worst_here);
    worst = std::max(worst, worst_here);
  }
  std::printf("CAD plate with a hole: max |gamma - ref| = %.2e\n", worst);
}

TEST(TrimmedFaceElements, SphereFacePolesAndSeam) {
  // OpenCASCADE's sphere: one face whose loop runs along the seam and two degenerate pole
  // edges. Cells at a pole lose a vertex; the surface area of their slivers is kept (the
  // element area sums to 4 pi R^2). gamma against the analytic ball, at the poles, on the
  // seam and elsewhere.
  constexpr double pi = std::numbers::pi;
  const double R = 1.0, h = 0.1, dx = 0.05;
  double worst = 0;
  for (auto side : {cad::FluidSide::inside, cad::FluidSide::outside}) {
    const bool inside = side == cad::FluidSide::inside;
    WallSet<3> walls;
    for (auto& w : cad::faces_to_walls(BRepPrimAPI_MakeSphere(R).Shape(), side, 1.0)) walls.add(w);
    const auto el = elements_from_walls<3>(walls, dx, {});
    EXPECT_NEAR(std::accumulate(el.area.begin(), el.area.end(), 0.0) / (4 * pi * R * R), 1.0,
                1e-10);
    const GeometricShepard<3> fast(el, h);
    std::vector<std::size_t> all(el.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    for (const Vec3d& dir : {Vec3d(0, 0, 1), Vec3d(0, 0, -1), Vec3d(1, 0, 0.3).normalized(),
                             Vec3d(-0.4, 0.7, 0.2).normalized()}) {
      for (double d : {1.5, 1.0, 0.5, 0.2, 0.05, 0.0}) {
        const double r = inside ? R - d * h : R + d * h;
        const double ref = test::reference_gamma_ball(r, R, h, inside);
        const Vec3d x = r * dir;
        const double e = std::max(std::abs(shepard_geometric<3>(el, x, h) - ref),
                                  std::abs(fast(el, all, x) - ref));
        worst = std::max(worst, e);
        EXPECT_LT(e, 0.005) << "inside " << inside << " dir " << dir.transpose() << " d/h " << d;
      }
    }
  }
  std::printf("CAD sphere face (poles, seam) vs the ball: max |gamma - ref| = %.2e\n", worst);
}
