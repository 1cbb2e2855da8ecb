// Ghosts at the convex rim of a CAD cylinder standing as a pillar in the fluid (fluid outside:
// the cylindrical side meets the planar top at a convex edge; boundary/ghost/convex_edges.hpp's
// partition of unity with a curved face). The fluid is a midpoint rule in (r, phi, z): rings of
// square cells outside the side at every height and inside it above the top, so the top's
// mirror images are cells of the same rule and the side's (mirror_beta: volume beta V) are
// close to them. Reference: the same rule over the whole space (the disc and the rings at every
// height, no wall); its own floor is the infinite cylinder's sum (the side alone, fluid at every
// height outside it) at the same points, the error of the curved mirror on this rule.
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <BRepPrimAPI_MakeCylinder.hxx>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gp_Ax2.hxx>
#include <iostream>
#include <memory>
#include <numbers>
#include <vector>

#include "../support/ghost_fill.hpp"
#include "../support/step_file.hpp"
#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/kernels/wendland.hpp"

namespace curvsph {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kH = 1.0, kR = 6.0,
                 kDr = 0.25;  // R = 6 h (density_preserving has its root), cells h / 4

struct Cells {
  std::vector<Vec<3>> x;
  std::vector<double> vol;
};

// Midpoint cells of the rings r0 < r < r1 (width kDr, about square cells) times [z0, z1].
void rings(Cells& c, double r0, double r1, double z0, double z1) {
  const int nr = static_cast<int>(std::lround((r1 - r0) / kDr));
  const int nz = static_cast<int>(std::lround((z1 - z0) / kDr));
  for (int i = 0; i < nr; ++i) {
    const double r = r0 + (i + 0.5) * kDr;
    const int nphi = std::max(6, static_cast<int>(std::lround(2 * kPi * r / kDr)));
    const double dphi = 2 * kPi / nphi;
    for (int j = 0; j < nphi; ++j)
      for (int k = 0; k < nz; ++k) {
        const double phi = (j + 0.5) * dphi;
        // Only the cells that can reach the points near the rim point (R, 0, 0) or ghost into
        // their reach: a source within 2h of the wall, its image at most 3.2 h deep
        // (density_preserving at R = 6 h), the points within 1.5 h of the rim point.
        const Vec3d p(r * std::cos(phi), r * std::sin(phi), z0 + (k + 0.5) * kDr);
        if ((p - Vec3d(kR, 0, 0)).norm() > 9 * kH) continue;
        c.x.emplace_back(static_cast<Real>(r * std::cos(phi)), static_cast<Real>(r * std::sin(phi)),
                         static_cast<Real>(z0 + (k + 0.5) * kDr));
        c.vol.push_back(r * kDr * dphi * kDr);
      }
  }
}

// sum V W over the cells and their ghosts (volume beta V) at each point of `at`.
std::vector<double> fill(const WallSet<3>* walls, GhostMapKind map, const Cells& c,
                         const std::vector<Vec<3>>& at) {
  return curvsph::test::ghost_fill(walls, map, c, at, kH);
}

TEST(ConvexRim, CadPillarRimFillsTheSupport) {
  // The rim r = R, z = 0 of a pillar -12 h < z < 0; points at 0.25, 1 and 1.5 h from it, at
  // angles from along the side (-90 degrees) to over the top (180 degrees).
  std::vector<Vec<3>> at;
  for (double rho : {0.25, 1.0, 1.5})
    for (double frac : {0.05, 0.3, 0.5, 0.7, 0.95}) {
      const double a = (-90 + frac * 270) * kPi / 180;
      at.emplace_back(static_cast<Real>(kR + rho * kH * std::cos(a)), 0,
                      static_cast<Real>(rho * kH * std::sin(a)));
    }
  const double reach = 4 * kH;  // cells that reach `at` or ghost into its reach
  Cells pillar, side, whole;
  rings(pillar, kR, kR + reach, -reach, reach);
  rings(pillar, 0, kR, 0, reach);
  rings(side, kR, kR + reach, -reach, reach);
  whole = side;
  rings(whole, 0, kR, -reach, reach);

  WallSet<3> infinite;
  infinite.add(
      std::make_shared<CylinderWall>(Vec3d::Zero(), Vec3d::UnitZ(), kR, FluidSide::outside));
  const auto dir =
      std::filesystem::temp_directory_path() / ("curvsph_convex_rim_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  test::write_step(
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -12 * kH), gp_Dir(0, 0, 1)), kR, 12 * kH)
          .Shape(),
      dir / "pillar.step");
  const WallSet<3> cad =
      parse_walls<3>(YAML::Load("[{shape: cad, file: pillar.step, fluid: outside}]"),
                     (dir / "case.yaml").string(), dir);
  std::filesystem::remove_all(dir);

  const auto ref = fill(nullptr, GhostMapKind::mirror, whole, at);
  for (GhostMapKind map :
       {GhostMapKind::mirror, GhostMapKind::mirror_beta, GhostMapKind::density_preserving}) {
    const auto inf = fill(&infinite, map, side, at);
    const auto rim = fill(&cad, map, pillar, at);
    double floor = 0, worst = 0, hi = 0;
    for (std::size_t a = 0; a < at.size(); ++a) {
      const bool beside = at[a][0] > kR;  // the infinite cylinder's fluid
      std::cout << to_string(map) << " (" << at[a][0] - kR << ", " << at[a][2] << "): whole "
                << ref[a] << ", rim " << rim[a] / ref[a] << ", infinite "
                << (beside ? inf[a] / ref[a] : 0.0) << "\n";
      if (beside) floor = std::max(floor, std::abs(inf[a] / ref[a] - 1));
      worst = std::max(worst, std::abs(rim[a] / ref[a] - 1));
      hi = std::max(hi, rim[a] / ref[a]);
    }
    std::cout << to_string(map) << ": rim sum / whole up to " << hi << ", worst |rim / whole - 1| "
              << worst << "; infinite cylinder's floor " << floor << "\n";
    // mirror_beta is exact on this rule (beta = the rings' volume ratio): floor 2.5e-7; the
    // rim was up to 1.75 times the reference with the images at full volume
    // (mirror 1.88, density_preserving 1.76).
    if (map == GhostMapKind::mirror_beta) EXPECT_LT(worst, 1e-5);
    // The other maps: no worse at the rim than the side alone (floors 0.064 for the mirror,
    // 6.8e-4 for density_preserving).
    else
      EXPECT_LE(worst, floor + 1e-4) << to_string(map);
  }
}

}  // namespace
}  // namespace curvsph
