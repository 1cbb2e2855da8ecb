// A closed CAD solid is one wall (cad_solid_wall.hpp): a box and a cylinder made by
// OpenCASCADE, written to STEP, read back through a case's `walls:` list, against the analytic
// signed distance at points near faces, edges and corners, inside and outside.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <UnitsMethods.hxx>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <random>

#include "../support/step_file.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/cad/cad_import.hpp"
#include "curvsph/cad/cad_solid_wall.hpp"
#include "curvsph/geometry/wall_parser.hpp"

using namespace curvsph;

namespace {

std::filesystem::path temp_dir() {
  const auto d =
      std::filesystem::temp_directory_path() / ("curvsph_cad_solid_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d;
}

using curvsph::test::write_step;

WallSet<3> read_case_walls(const std::filesystem::path& dir, const std::string& file,
                           const std::string& fluid) {
  return parse_walls<3>(YAML::Load("[{shape: cad, file: " + file + ", fluid: " + fluid + "}]"),
                        (dir / "case.yaml").string(), dir);
}

// Outward signed distance (> 0 outside) and the foot of an axis-aligned box [lo, hi].
double box_sdf(const Vec3d& x, const Vec3d& lo, const Vec3d& hi, Vec3d& foot) {
  const Vec3d c = x.cwiseMax(lo).cwiseMin(hi);
  if (c != x) {
    foot = c;
    return (x - c).norm();
  }
  double best = 1e300;
  for (int a = 0; a < 3; ++a)
    for (double face : {lo[a], hi[a]})
      if (std::abs(x[a] - face) < best) {
        best = std::abs(x[a] - face);
        foot = x;
        foot[a] = face;
      }
  return -best;
}

// Outward signed distance of the cylinder of radius R about the z axis, z in [0, H].
double cylinder_sdf(const Vec3d& x, double R, double H) {
  const double dr = std::hypot(x.x(), x.y()) - R;
  const double dz = std::max(-x.z(), x.z() - H);
  if (dr > 0 || dz > 0) return std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
  return std::max(dr, dz);
}

// Points at distances in [-reach, reach] across every face, edge and corner of a box.
std::vector<Vec3d> probe_box(const Vec3d& lo, const Vec3d& hi, double reach, int n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1), s(-reach, reach);
  std::vector<Vec3d> pts;
  for (int i = 0; i < n; ++i) {
    Vec3d x;
    // Each axis: near lo, near hi, or anywhere between (faces: 1 near axis, edges: 2, corners: 3).
    for (int a = 0; a < 3; ++a) {
      const int k = static_cast<int>(3 * u(rng));
      x[a] = k == 0 ? lo[a] + s(rng) : k == 1 ? hi[a] + s(rng) : lo[a] + (hi[a] - lo[a]) * u(rng);
    }
    pts.push_back(x);
  }
  return pts;
}

TEST(CadSolidWall, BoxIsOneWallWithTheAnalyticSignedDistance) {
  const auto dir = temp_dir();
  const Vec3d lo(0.1, -0.2, 0.05), hi(0.3, 0.1, 0.45);
  write_step(
      BRepPrimAPI_MakeBox(gp_Pnt(lo.x(), lo.y(), lo.z()), gp_Pnt(hi.x(), hi.y(), hi.z())).Shape(),
      dir / "box.step");
  for (const std::string fluid : {"inside", "outside"}) {
    const WallSet<3> walls = read_case_walls(dir, "box.step", fluid);
    ASSERT_EQ(walls.size(), 1u) << fluid;
    const auto* solid = dynamic_cast<const cad::CadSolidWall*>(&walls[0]);
    ASSERT_NE(solid, nullptr);
    EXPECT_EQ(solid->faces().size(), 6u);
    const double s = fluid == "inside" ? -1.0 : 1.0;  // fluid distance = s * outward distance
    double worst = 0, worst_n = 0, worst_foot = 0;
    int edge_or_corner = 0;
    for (const Vec3d& x : probe_box(lo, hi, 0.03, 2000)) {
      Vec3d foot = Vec3d::Zero();
      const double exact = s * box_sdf(x, lo, hi, foot);
      const WallPoint<3> p = walls[0].closest(x);
      worst = std::max(worst, std::abs(p.distance - exact));
      worst_foot = std::max(worst_foot, (p.foot - foot).norm());
      // Normal into the fluid: foot -> point times the sign of the distance, as box corners do.
      const Vec3d r = x - foot;
      if (r.norm() > 1e-6)
        worst_n = std::max(worst_n, (p.normal - exact / r.norm() * r / std::abs(exact)).norm());
      EXPECT_NEAR((p.foot + p.distance * p.normal - x).norm(), 0.0, 1e-9);
      const int clamped = (x.array() < lo.array()).count() + (x.array() > hi.array()).count();
      if (clamped >= 2) {
        ++edge_or_corner;
        EXPECT_EQ(p.k1, 0.0);
      }
      EXPECT_EQ(solid->classify(x), exact > 0 ? (s < 0 ? 1 : -1) : (s < 0 ? -1 : 1))
          << x.transpose();
    }
    std::cout << "box, fluid " << fluid << ": max |d - exact| = " << worst
              << ", max |foot - exact| = " << worst_foot << ", max |n - exact| = " << worst_n
              << " (" << edge_or_corner << " points beyond an edge or corner)\n";
    EXPECT_LT(worst, 1e-9);
    EXPECT_LT(worst_foot, 1e-8);
    EXPECT_LT(worst_n, 1e-6);
    EXPECT_GT(edge_or_corner, 300);
  }
}

TEST(CadSolidWall, CylinderIsOneWallWithTheAnalyticSignedDistance) {
  const auto dir = temp_dir();
  const double R = 0.1, H = 0.3;
  write_step(BRepPrimAPI_MakeCylinder(R, H).Shape(), dir / "cylinder.step");
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1), s(-0.02, 0.02);
  for (const std::string fluid : {"inside", "outside"}) {
    const WallSet<3> walls = read_case_walls(dir, "cylinder.step", fluid);
    ASSERT_EQ(walls.size(), 1u);
    const auto* solid = dynamic_cast<const cad::CadSolidWall*>(&walls[0]);
    ASSERT_NE(solid, nullptr);
    const double sign = fluid == "inside" ? -1.0 : 1.0;
    double worst = 0;
    int wrong_side = 0;
    for (int i = 0; i < 1500; ++i) {
      // Near the side, near a cap, near a rim (both cap and side), anywhere around.
      const int kind = i % 4;
      const double th = 2 * M_PI * u(rng);
      const double rho = kind == 1   ? R * std::sqrt(u(rng))
                         : kind == 3 ? 1.3 * R * u(rng)
                                     : R + s(rng);
      const double z = kind == 0   ? H * u(rng)
                       : kind == 3 ? -0.05 + 0.4 * u(rng)
                                   : (u(rng) < 0.5 ? 0 : H) + s(rng);
      const Vec3d x(rho * std::cos(th), rho * std::sin(th), z);
      if (rho < 1e-3 * R) continue;  // on the axis every side point is a foot
      const double exact = sign * cylinder_sdf(x, R, H);
      const WallPoint<3> p = walls[0].closest(x);
      worst = std::max(worst, std::abs(p.distance - exact));
      if ((p.distance > 0) != (exact > 0)) ++wrong_side;
      EXPECT_NEAR((p.foot + p.distance * p.normal - x).norm(), 0.0, 1e-8 * R);
    }
    std::cout << "cylinder, fluid " << fluid << ": max |d - exact| = " << worst << "\n";
    EXPECT_LT(worst, 1e-8 * R);
    EXPECT_EQ(wrong_side, 0);
    // Boundary elements: every face of the solid (side, two discs), normals into the fluid.
    const auto el = elements_from_wall<3>(walls[0], 0.02, {});
    const double area = std::accumulate(el.area.begin(), el.area.end(), 0.0);
    // The discs' rims are polygons of n = 2 pi R / (dx / 4) chords, short of pi R^2 by
    // (2 pi / n)^2 / 6 of it: 1.0e-4 of the whole here.
    const double n = 2 * M_PI * R / (0.25 * 0.02);
    const double chords = 2 * M_PI * R * R * std::pow(2 * M_PI / n, 2) / 6;
    EXPECT_NEAR(area / (2 * M_PI * R * H + 2 * M_PI * R * R - chords), 1.0, 1e-5);
    WallSet<3> faces;
    for (const auto& f : solid->faces()) faces.add(f);
    EXPECT_EQ(el.size(), elements_from_walls<3>(faces, 0.02, {}).size());
    int wrong_normal = 0;
    for (std::size_t j = 0; j < el.size(); ++j) {
      const Vec3d c = el.centre[j];
      const bool cap = std::abs(c.z()) < 1e-9 || std::abs(c.z() - H) < 1e-9;
      const Vec3d inward = cap ? Vec3d(0, 0, 0.5 * H - c.z()) : Vec3d(-c.x(), -c.y(), 0);
      if ((el.normal[j].dot(inward) > 0) != (fluid == "inside")) ++wrong_normal;
    }
    EXPECT_EQ(wrong_normal, 0);
  }
}

// Outward signed distance of the counter-clockwise triangle t in the x-y plane.
double triangle_sdf(const Vec2d& x, const std::array<Vec2d, 3>& t) {
  double d = 1e300;
  bool inside = true;
  for (int i = 0; i < 3; ++i) {
    const Vec2d a = t[i], e = t[(i + 1) % 3] - a;
    const double s = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    d = std::min(d, (x - a - s * e).norm());
    if (e.x() * (x - a).y() - e.y() * (x - a).x() < 0) inside = false;
  }
  return inside ? -d : d;
}

TEST(CadSolidWall, SharpEdgeOfAThirtyDegreePrismTakesTheSideFromTheSolid) {
  // A prism on a triangle with a 30-degree corner: beyond that edge a face's normal sees
  // points on the wrong side (more than 90 degrees between the faces' normals).
  const auto dir = temp_dir();
  const double L = 0.3, H = 0.2, th = M_PI / 6;
  const std::array<Vec2d, 3> tri{Vec2d(0, 0), Vec2d(L, 0),
                                 Vec2d(L * std::cos(th), L * std::sin(th))};
  BRepBuilderAPI_MakePolygon poly(gp_Pnt(0, 0, 0), gp_Pnt(L, 0, 0),
                                  gp_Pnt(tri[2].x(), tri[2].y(), 0), true);
  const TopoDS_Shape prism =
      BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(poly.Wire()).Face(), gp_Vec(0, 0, H)).Shape();
  write_step(prism, dir / "prism.step");
  const WallSet<3> walls = read_case_walls(dir, "prism.step", "inside");
  ASSERT_EQ(walls.size(), 1u);
  const auto* solid = dynamic_cast<const cad::CadSolidWall*>(&walls[0]);
  ASSERT_NE(solid, nullptr);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ang(0, 2 * M_PI), rad(0, 0.05), z(0.02, H - 0.02);
  double worst = 0;
  int wrong = 0, ambiguous = 0;
  for (int i = 0; i < 1000; ++i) {
    // Around the 30-degree edge (the z axis), all round.
    const double a = ang(rng), r = rad(rng);
    const Vec3d x(r * std::cos(a), r * std::sin(a), z(rng));
    const double dz = std::max(-x.z(), x.z() - H), dr = triangle_sdf(x.head<2>(), tri);
    const double out =
        dr > 0 || dz > 0 ? std::hypot(std::max(dr, 0.0), std::max(dz, 0.0)) : std::max(dr, dz);
    const double exact = -out;  // fluid inside
    const WallPoint<3> p = walls[0].closest(x);
    worst = std::max(worst, std::abs(p.distance - exact));
    if ((p.distance > 0) != (exact > 0)) ++wrong;
    // Points whose nearest faces tie (an edge foot) and disagree on the side: the faces'
    // normals alone cannot answer there.
    int plus = 0, minus = 0;
    for (const auto& f : solid->faces()) {
      const WallPoint<3> q = f->closest(x);
      if (std::abs(std::abs(q.distance) - std::abs(exact)) < 1e-9)
        (q.distance > 0 ? plus : minus)++;
    }
    ambiguous += plus > 0 && minus > 0;
    EXPECT_NEAR((p.foot + p.distance * p.normal - x).norm(), 0.0, 1e-9);
  }
  std::cout << "30-degree prism edge: max |d - exact| = " << worst << ", wrong sides: " << wrong
            << " (" << ambiguous << " points where the nearest faces' normals disagree)\n";
  EXPECT_LT(worst, 1e-9);
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(ambiguous, 100);
}

}  // namespace
