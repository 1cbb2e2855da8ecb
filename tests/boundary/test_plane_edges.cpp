// Ghosts at the edge where a planar floor meets a curved side perpendicular to it (an upright
// cylinder's floor rim): the analytic walls (`cylinder` + `plane`, two walls) and the same solid
// from a STEP file (one CAD wall of three faces). Reference: the same ghost map on the infinite
// cylinder alone, whose fluid reaches below the floor level (z < 0) — the floor, a mirror plane
// of the side, must give there exactly what the fluid below it gave (the side's images of the
// mirrored fluid are the mirror images of its side images). Both are the same midpoint rule in
// (r, phi, z), so the comparison is free of the rule's own error; sum V W at points approaching
// the rim must agree within 1e-3.
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <UnitsMethods.hxx>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <vector>

#include "../support/ghost_fill.hpp"
#include "../support/step_file.hpp"
#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/plane.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/kernels/wendland.hpp"

namespace curvsph {
namespace {

constexpr double kPi = std::numbers::pi;
// The study's cylinder (cad_at_rest): R = 0.06, h = 2 dx at H/dx = 6 (R = 2.25 h).
constexpr double kR = 0.06, kH = 0.08 / 3;

struct Cells {
  std::vector<Vec<3>> x;
  std::vector<double> vol;
};

// Midpoint cells of the disc r < R (nr rings, about square cells) times [z0, z1] (nz layers).
Cells cells(int nr, double z0, double z1, int nz) {
  Cells c;
  const double dr = kR / nr, dz = (z1 - z0) / nz;
  for (int i = 0; i < nr; ++i) {
    const double r = (i + 0.5) * dr;
    const int nphi = std::max(6, static_cast<int>(std::lround(2 * kPi * r / dr)));
    const double dphi = 2 * kPi / nphi;
    for (int j = 0; j < nphi; ++j)
      for (int k = 0; k < nz; ++k) {
        const double phi = (j + 0.5) * dphi;
        c.x.emplace_back(static_cast<Real>(r * std::cos(phi)), static_cast<Real>(r * std::sin(phi)),
                         static_cast<Real>(z0 + (k + 0.5) * dz));
        c.vol.push_back(r * dr * dphi * dz);
      }
  }
  return c;
}

// sum V W over the cells and their ghosts (volume weight beta) at each point of `at`.
std::vector<double> fill(const WallSet<3>& walls, GhostMapKind map, const Cells& c,
                         const std::vector<Vec<3>>& at) {
  return curvsph::test::ghost_fill(&walls, map, c, at, kH);
}

using curvsph::test::write_step;

TEST(PlaneEdges, CylinderFloorRimFillsAsTheInfiniteCylinder) {
  const double support = 2 * kH;
  // Points at 0.2, 0.5 and 1 h from the side, 0.2, 0.5 and 1 h above the floor.
  std::vector<Vec<3>> at;
  for (double dr : {0.2, 0.5, 1.0})
    for (double dz : {0.2, 0.5, 1.0})
      at.emplace_back(static_cast<Real>(kR - dr * kH), 0, static_cast<Real>(dz * kH));
  const int nr = 12, per_h = 4;      // exact either way: the same rule on both sides
  const double top = 2.5 * support;  // the cells that can reach `at`, or ghost into reach
  const int nz = static_cast<int>(std::lround(top / kH * per_h));
  const Cells above = cells(nr, 0, top, nz), both = cells(nr, -top, top, 2 * nz);

  WallSet<3> infinite, analytic;
  infinite.add(
      std::make_shared<CylinderWall>(Vec3d::Zero(), Vec3d::UnitZ(), kR, FluidSide::inside));
  analytic.add(
      std::make_shared<CylinderWall>(Vec3d::Zero(), Vec3d::UnitZ(), kR, FluidSide::inside));
  analytic.add(std::make_shared<PlaneWall<3>>(Vec3d::Zero(), Vec3d::UnitZ()));
  const auto dir = std::filesystem::temp_directory_path() /
                   ("curvsph_plane_edges_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_step(BRepPrimAPI_MakeCylinder(kR, 4 * top).Shape(), dir / "cylinder.step");
  const WallSet<3> cad =
      parse_walls<3>(YAML::Load("[{shape: cad, file: cylinder.step, fluid: inside}]"),
                     (dir / "case.yaml").string(), dir);

  for (GhostMapKind map :
       {GhostMapKind::mirror, GhostMapKind::mirror_beta, GhostMapKind::density_preserving}) {
    const auto ref = fill(infinite, map, both, at);
    const auto an = fill(analytic, map, above, at);
    const auto cd = fill(cad, map, above, at);
    double worst_an = 0, worst_cad = 0;
    for (std::size_t a = 0; a < at.size(); ++a) {
      std::cout << to_string(map) << " r = R - " << (kR - at[a][0]) / kH
                << " h, z = " << at[a][2] / kH << " h: infinite " << ref[a] << ", cylinder + plane "
                << an[a] << ", CAD " << cd[a] << "\n";
      worst_an = std::max(worst_an, std::abs(an[a] - ref[a]));
      worst_cad = std::max(worst_cad, std::abs(cd[a] - ref[a]));
    }
    std::cout << to_string(map) << ": worst |fill - infinite|: cylinder + plane " << worst_an
              << ", CAD " << worst_cad << "\n";
    EXPECT_LT(worst_an, 1e-3) << to_string(map);
    EXPECT_LT(worst_cad, 1e-3) << to_string(map);
  }
  std::filesystem::remove_all(dir);
}

TEST(PlaneEdges, NoImageWhereTheWallIsNotSymmetricAboutThePlane) {
  // A cylinder leaning on the floor (axis 20 degrees off the vertical): its reflection across
  // the floor is another cylinder, so no corner image; an upright one gets them.
  const std::vector<Vec<3>> x = {
      Vec<3>(static_cast<Real>(kR - 0.3 * kH), 0, static_cast<Real>(0.3 * kH))};
  for (double tilt : {0.0, 20.0}) {
    WallSet<3> w;
    const double t = tilt * kPi / 180;
    w.add(std::make_shared<CylinderWall>(Vec3d::Zero(), Vec3d(std::sin(t), 0, std::cos(t)), kR,
                                         FluidSide::inside));
    w.add(std::make_shared<PlaneWall<3>>(Vec3d::Zero(), Vec3d::UnitZ()));
    GhostOptions<3> opt;
    opt.map = GhostMapKind::mirror_beta;
    opt.support = 2 * kH;
    GhostSet<3> g;
    g.build(x, {Vec<3>::Zero()}, w, opt);
    int doubles = 0;
    for (auto r : g.reflections) doubles += r == 2;
    EXPECT_EQ(doubles, tilt == 0.0 ? 1 : 0) << tilt;
    EXPECT_EQ(g.size(), tilt == 0.0 ? 3u : 2u) << tilt;
    EXPECT_EQ(g.corners.size(), tilt == 0.0 ? 1u : 0u) << tilt;
  }
}

}  // namespace
}  // namespace curvsph
