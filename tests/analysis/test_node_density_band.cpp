// The node-density analysis' source band (Vela Vela §7): every fluid particle is mirrored, so
// a ghost near depth 2h has its whole kernel support populated, unlike the solver's band
// (fluid within 2h only). Checked on a small periodic lattice cylinder against brute-force
// sums of eq. 3 and the closed-form ghost shell of the density-preserving map (eq. 21).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "../support/quiet_run.hpp"
#include "curvsph/analysis/node_density.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"

namespace curvsph {
namespace {

constexpr double kR = 0.25;    // cylinder radius
constexpr double kDx = 0.016;  // lattice spacing
constexpr double kH = 1.5 * kDx;
constexpr int kLayers = 10;  // periodic over z in [0, kLayers dx)

struct LatticeCylinder {
  std::vector<Vec<3>> x;
  WallSet<3> walls;
  CellList<3> cells;
  WendlandC2<3> W{static_cast<Real>(kH)};
  double length = kLayers * kDx;

  LatticeCylinder() {
    walls = parse_walls<3>(
        YAML::Load("[{shape: cylinder, point: [0, 0, 0], axis: [0, 0, 1], radius: 0.25, "
                   "fluid: inside}]"),
        "walls.yaml", ".");
    const int m = static_cast<int>(std::ceil(kR / kDx));
    for (int i = -m; i < m; ++i)
      for (int j = -m; j < m; ++j)
        for (int k = 0; k < kLayers; ++k) {
          const double px = (i + 0.5) * kDx, py = (j + 0.5) * kDx;
          if (std::hypot(px, py) < kR - 0.25 * kDx)
            x.emplace_back(Vec<3>(static_cast<Real>(px), static_cast<Real>(py),
                                  static_cast<Real>((k + 0.5) * kDx)));
        }
    cells.configure(W.support, Vec3d(-0.4, -0.4, 0.0), Vec3d(0.4, 0.4, length),
                    {false, false, true});
    cells.build(x);
  }

  // Eq. 3 by brute force over every fluid particle and every ghost (minimum image along z).
  double brute_n(const Vec<3>& at, const GhostSet<3>& G) const {
    auto w = [&](const Vec<3>& y) {
      Vec3d r = (at - y).cast<double>();
      r.z() -= length * std::round(r.z() / length);
      return static_cast<double>(W.value(static_cast<Real>(r.norm())));
    };
    double s = 0;
    for (const auto& y : x) s += w(y);
    for (std::size_t g = 0; g < G.size(); ++g) s += G.beta[g] * w(G.x[g]);
    return s;
  }
};

TEST(NodeDensityBand, DefaultMirrorsEveryParticle) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(node_density_source_band(YAML::Load("{}"), "c.yaml"), inf);
  EXPECT_EQ(node_density_source_band(YAML::Load("{ghost_support: all}"), "c.yaml"), inf);
  EXPECT_DOUBLE_EQ(node_density_source_band(YAML::Load("{ghost_support: 0.1}"), "c.yaml"), 0.1);
  EXPECT_THROW(node_density_source_band(YAML::Load("{ghost_support: -1}"), "c.yaml"), InputError);
}

TEST(NodeDensityBand, GhostNearTwoHHasFullSupportOnlyInAnalysisBand) {
  const LatticeCylinder L;
  const double support = 2 * kH;
  const double band = node_density_source_band(YAML::Load("{}"), "c.yaml");
  GhostNodeDensity<3> all, solver;
  ghost_node_density<3>(L.x, L.cells, L.walls, GhostMapKind::density_preserving, band, L.W, all);
  ghost_node_density<3>(L.x, L.cells, L.walls, GhostMapKind::density_preserving, support, L.W,
                        solver);

  // Analysis band: one ghost per fluid particle, none refused.
  ASSERT_EQ(all.ghosts.size(), L.x.size());
  EXPECT_TRUE(all.ghosts.no_root.empty());
  EXPECT_TRUE(all.ghosts.penetrated.empty());
  std::vector<Index> src = all.ghosts.source;
  std::sort(src.begin(), src.end());
  std::vector<Index> iota(L.x.size());
  std::iota(iota.begin(), iota.end(), Index{0});
  EXPECT_EQ(src, iota);
  // Solver band: exactly the particles within 2h (brute-force distance to the axis).
  std::size_t within = 0;
  for (const auto& p : L.x) within += kR - std::hypot(double(p.x()), double(p.y())) < support;
  EXPECT_EQ(solver.ghosts.size(), within);

  // The ghost shell of the analysis band is 4h deep or more, so a ghost at depth ~2h has its
  // whole support inside it. Closed form (Vela Vela eq. 21): a source at radius r goes to
  // sqrt(2 R^2 - r^2), so the deepest ghost comes from the innermost source.
  double rmin = kR, zmax = 0;
  for (const auto& p : L.x) rmin = std::min(rmin, std::hypot(double(p.x()), double(p.y())));
  for (double z : all.ghosts.depth) zmax = std::max(zmax, z);
  EXPECT_NEAR(zmax, std::sqrt(2 * kR * kR - rmin * rmin) - kR, 1e-9);
  ASSERT_GE(zmax, 2 * support);

  // Deepest ghost of the solver band (its shell ends there): the same source's ghost in both
  // bands, n against the brute-force sum and against the interior lattice value n0.
  std::size_t gs = 0;
  for (std::size_t g = 0; g < solver.ghosts.size(); ++g)
    if (solver.ghosts.depth[g] > solver.ghosts.depth[gs]) gs = g;
  const Index s = solver.ghosts.source[gs];
  const std::size_t ga = static_cast<std::size_t>(
      std::find(all.ghosts.source.begin(), all.ghosts.source.end(), s) - all.ghosts.source.begin());
  ASSERT_LT(ga, all.ghosts.size());
  EXPECT_NEAR(all.ghosts.depth[ga], solver.ghosts.depth[gs], 1e-12);
  EXPECT_GT(solver.ghosts.depth[gs], 0.75 * support);  // "near 2h"
  const double n_all = L.brute_n(all.ghosts.x[ga], all.ghosts);
  const double n_solver = L.brute_n(solver.ghosts.x[gs], solver.ghosts);
  EXPECT_NEAR(all.n_ghost[ga], n_all, 1e-5 * n_all);
  EXPECT_NEAR(solver.n_ghost[gs], n_solver, 1e-5 * n_solver);
  // Interior reference: a particle on the axis (fluid only, its support is all fluid).
  std::size_t c = 0;
  for (std::size_t i = 0; i < L.x.size(); ++i)
    if (L.x[i].head<2>().norm() < L.x[c].head<2>().norm()) c = i;
  const double n0 = L.brute_n(L.x[c], GhostSet<3>{});
  // Full support: the density-preserving ghost keeps the interior's node density (the lattice
  // is sheared by the map, hence a few per cent); the solver band's shell ends at this ghost,
  // so about half of its support (F(0) = 1/2 beyond a plane) is empty.
  RecordProperty("ghost_depth_over_2h", std::to_string(all.ghosts.depth[ga] / support));
  RecordProperty("n_all_over_n0", std::to_string(n_all / n0));
  RecordProperty("n_solver_over_n0", std::to_string(n_solver / n0));
  EXPECT_NEAR(n_all / n0, 1.0, 0.05);
  EXPECT_LT(n_solver / n0, 0.75);
  EXPECT_GT(n_solver / n0, 0.35);

  // The analysis band's ghost closest to depth 2h (from below, the deepest the figure
  // counts): its support reaches depth 4h <= the shell, so its n is complete too.
  std::size_t g2 = 0;
  for (std::size_t g = 0; g < all.ghosts.size(); ++g)
    if (all.ghosts.depth[g] < support &&
        (all.ghosts.depth[g2] >= support || all.ghosts.depth[g] > all.ghosts.depth[g2]))
      g2 = g;
  ASSERT_LT(all.ghosts.depth[g2], support);
  EXPECT_GT(all.ghosts.depth[g2], 0.95 * support);
  const double n_2h = L.brute_n(all.ghosts.x[g2], all.ghosts);
  EXPECT_NEAR(all.n_ghost[g2], n_2h, 1e-5 * n_2h);
  RecordProperty("n_2h_over_n0", std::to_string(n_2h / n0));
  EXPECT_NEAR(n_2h / n0, 1.0, 0.05);
}

// Every particle mirrored around a small convex obstacle: the density-preserving map has no
// root for sources deeper than R (sqrt 2 - 1) (G(z) = z - z^2/(2R) peaks at R/2 = -G(-d)), the
// mirror map none beyond d = R (the centre). Those sources get no ghost and are listed,
// nothing throws: the set-up refusal is for the solver's 2h band only.
TEST(NodeDensityBand, SourcesWithoutRootAreCountedNotRefused) {
  constexpr double R = 0.2, dx = 0.02;
  const WallSet<2> walls = parse_walls<2>(
      YAML::Load("[{shape: circle, center: [0, 0], radius: 0.2, fluid: outside}]"), "w.yaml", ".");
  std::vector<Vec<2>> x;
  for (int i = -25; i < 25; ++i)
    for (int j = -25; j < 25; ++j) {
      const double px = (i + 0.5) * dx, py = (j + 0.5) * dx;
      if (std::hypot(px, py) > R + 0.25 * dx)
        x.emplace_back(Vec<2>(static_cast<Real>(px), static_cast<Real>(py)));
    }
  const WendlandC2<2> W(static_cast<Real>(1.5 * dx));
  CellList<2> cells;
  cells.configure(W.support, Vec3d(-0.5, -0.5, 0), Vec3d(0.5, 0.5, 0), {true, true, false});
  cells.build(x);
  const double band = node_density_source_band(YAML::Load("{}"), "c.yaml");
  for (const auto map : {GhostMapKind::density_preserving, GhostMapKind::mirror}) {
    const double dmax = map == GhostMapKind::mirror ? R : R * (std::sqrt(2.0) - 1.0);
    std::size_t deep = 0;
    for (const auto& p : x) {
      const double d = std::hypot(double(p.x()), double(p.y())) - R;
      ASSERT_GT(std::abs(d - dmax), 1e-6);  // no lattice point on the threshold
      deep += d > dmax;
    }
    GhostNodeDensity<2> nd;
    ASSERT_NO_THROW(ghost_node_density<2>(x, cells, walls, map, band, W, nd));
    EXPECT_GT(deep, 0u);
    EXPECT_EQ(nd.ghosts.no_root.size(), deep) << to_string(map);
    EXPECT_EQ(nd.ghosts.size() + deep, x.size()) << to_string(map);
  }
}

// The analysis of a case mirrors every fluid particle by default and reports the solver's
// band separately (small 2-D disk, no relaxation: the counts do not depend on it).
TEST(NodeDensityBand, AnalysisReportsBothBands) {
  const Case c = read_case(YAML::Load(R"(
name: band_disk
dimension: 2
resolution: {dx: 0.02, h_over_dx: 1.5}
domain: {min: [-0.32, -0.32], max: [0.32, 0.32]}
fluids:
  - {name: f, rho0: 1.0, region: {inside_walls: true}}
eos: {type: tait, c0: 10, gamma: 7, p0: 0}
walls:
  - {shape: circle, center: [0, 0], radius: 0.3, fluid: inside}
boundary: {method: ghost, map: density_preserving, velocity: free_slip}
time: {end: 0}
output: {vtk: false}
analysis: {node_density: {}}
)"),
                           "band_disk.yaml");
  const auto m = test::run_quiet(c);
  const long np = m["particles"];
  EXPECT_EQ(m["node_density_ghosts_density_preserving"].get<long>(), np);
  EXPECT_EQ(m["node_density_ghosts_mirror"].get<long>(), np);
  EXPECT_EQ(m["node_density_sources_without_ghost_density_preserving"].get<long>(), 0);
  // Fluid within 2h = 0.06 of the circle: the ring 0.24 < r < 0.3, 36 % of the disk.
  const long sb = m["node_density_ghosts_solver_band_density_preserving"];
  EXPECT_LT(sb, np / 2);
  EXPECT_GT(sb, np / 5);
  EXPECT_DOUBLE_EQ(m["ghost_node_density_dev_solver_band"].get<double>(),
                   m["ghost_node_density_dev_solver_band_density_preserving"].get<double>());
}

}  // namespace
}  // namespace curvsph
