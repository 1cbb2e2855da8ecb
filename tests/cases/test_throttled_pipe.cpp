// cases/throttled_pipe.yaml (Barker & Neethling §4.1): the case parses, its NURBS walls make
// the intended channel (throat L_y/2 wide at mid-length, L_y at the seam), they are smooth
// (C2) and match across the periodic seam, they reach >= 2h past it; a short coarse run
// keeps every particle inside and gives a finite flux variation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "curvsph/analysis/analysis.hpp"
#include "curvsph/analysis/throttled_pipe.hpp"
#include "curvsph/boundary/ghost/ghosts.hpp"
#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/nurbs/curve.hpp"
#include "curvsph/solver/solver.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

const std::filesystem::path kCase =
    std::filesystem::path(CURVSPH_SOURCE_DIR) / "cases/throttled_pipe.yaml";
constexpr double kLx = 0.024, kLy = 0.01;

WallSet<2> case_walls(const Case& c) {
  return parse_walls<2>(c.root["walls"], c.file_name(), c.file.parent_path());
}

TEST(ThrottledPipeCase, ParsesAsBarkersChannel) {
  const Case c = read_case(kCase);
  EXPECT_EQ(c.dimension, 2);
  EXPECT_DOUBLE_EQ(c.domain_max[0] - c.domain_min[0], kLx);
  EXPECT_DOUBLE_EQ(c.domain_max[1] - c.domain_min[1], kLy);
  EXPECT_TRUE(c.periodic[0]);
  EXPECT_FALSE(c.periodic[1]);
  EXPECT_DOUBLE_EQ(c.fluids.at(0).viscosity, 0.01);
  EXPECT_DOUBLE_EQ(c.fluids.at(0).rho0, 1000.0);
  EXPECT_EQ(c.fluids.at(0).region.kind, RegionSpec::Kind::inside_walls);  // the scalar form
  EXPECT_EQ(c.boundary.method, "ghost");
  EXPECT_EQ(c.boundary.map, "mirror_beta");
  EXPECT_EQ(c.boundary.velocity, "no_slip");
  EXPECT_GT(c.gravity[0], 0.0);
  const WallSet<2> walls = case_walls(c);
  ASSERT_EQ(walls.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto* w = dynamic_cast<const NurbsCurveWall*>(&walls[k]);
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->curve().degree(), 3);
    for (double wt : w->curve().weights()) EXPECT_EQ(wt, 1.0);
  }
}

TEST(ThrottledPipeCase, ThroatIsHalfTheChannelWidth) {
  const Case c = read_case(kCase);
  const WallSet<2> walls = case_walls(c);
  // Closest-point distance from the centre of the throat to each wall: L_y/4.
  for (std::size_t k = 0; k < 2; ++k) {
    const WallPoint<2> p = walls[k].closest(Vec2d(0.0, 0.0));
    EXPECT_NEAR(p.distance, kLy / 4, 1e-12) << "wall " << k;
    EXPECT_NEAR(p.foot.x(), 0.0, 1e-9);
    EXPECT_NEAR(std::abs(p.normal.y()), 1.0, 1e-12);
    EXPECT_LT(p.k1, 0.0);  // the wall bulges into the fluid at the throat
  }
  const ChannelGap throat = channel_gap(walls, 0.0, 0.0, 1e-4, 0.02);
  EXPECT_NEAR(throat.hi - throat.lo, kLy / 2, 1e-12);
  EXPECT_NEAR(throat.center(), 0.0, 1e-12);
  // The throat is the narrowest section; the seam is the full width L_y.
  for (int k = 0; k <= 48; ++k) {
    const double x = -kLx / 2 + kLx * k / 48;
    const ChannelGap g = channel_gap(walls, x, 0.0, 1e-4, 0.02);
    EXPECT_GE(g.hi - g.lo, kLy / 2 - 1e-12) << "x = " << x;
    EXPECT_LE(g.hi - g.lo, kLy + 1e-12) << "x = " << x;
  }
  EXPECT_NEAR(channel_gap(walls, -kLx / 2, 0.0, 1e-4, 0.02).half_width(), kLy / 2, 1e-12);
}

TEST(ThrottledPipeCase, WallsAreSmoothAndMatchAcrossTheSeam) {
  const Case c = read_case(kCase);
  const WallSet<2> walls = case_walls(c);
  const double reach = 2 * c.h();
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& w = dynamic_cast<const NurbsCurveWall&>(walls[k]);
    const auto& curve = w.curve();
    // The wall runs at least 2h past both seams, so particles there see it across the seam.
    EXPECT_LE(curve.point(curve.t0()).x(), -kLx / 2 - reach);
    EXPECT_GE(curve.point(curve.t1()).x(), kLx / 2 + reach);
    // Simple interior knots on a cubic: C2. Check curvature continuity at each knot.
    const auto& U = curve.knots();
    for (std::size_t i = 4; i + 4 < U.size(); ++i) {
      EXPECT_LT(U[i], U[i + 1]) << "repeated interior knot " << i;
      const double eps = 1e-7;
      const double ka = nurbs::signed_curvature(curve.eval(U[i] - eps));
      const double kb = nurbs::signed_curvature(curve.eval(U[i] + eps));
      EXPECT_NEAR(ka, kb, 1e-4 * (1 + std::abs(ka))) << "knot " << U[i];
    }
    // Seam: same height, horizontal tangent and zero curvature on both sides, and over the
    // whole band of 2h around it.
    for (double dxs : {-reach, -0.5 * reach, 0.0, 0.5 * reach, reach}) {
      const WallPoint<2> a = w.closest(Vec2d(-kLx / 2 + dxs, 0.0));
      const WallPoint<2> b = w.closest(Vec2d(kLx / 2 + dxs, 0.0));
      EXPECT_NEAR(a.foot.y(), b.foot.y(), 1e-15);
      EXPECT_NEAR(std::abs(a.foot.y()), kLy / 2, 1e-15);
      EXPECT_NEAR(a.normal.x(), 0.0, 1e-12);
      EXPECT_NEAR(b.normal.x(), 0.0, 1e-12);
      EXPECT_NEAR(a.k1, 0.0, 1e-9);
      EXPECT_NEAR(b.k1, 0.0, 1e-9);
    }
    // The kernel fits the wall: smallest radius of curvature > 2h at the case resolution.
    EXPECT_GT(w.min_radius_of_curvature(), reach);
  }
}

TEST(ThrottledPipeCase, GhostsWrapAndAreSeenAcrossTheSeam) {
  // Two particles 0.3 mm above the bottom wall, 0.1 mm either side of the periodic seam:
  // each gets its mirror ghost (flat wall: beta = 1, 0.3 mm below the wall) inside the
  // periodic box, and each sees the other's ghost through the periodic cell list.
  const Case c = read_case(kCase, {"resolution.dx=5e-4"});
  const WallSet<2> walls = case_walls(c);
  const Real support = static_cast<Real>(2 * c.h());
  CellList<2> cells;
  cells.configure(support, c.domain_min, c.domain_max, c.periodic);
  const std::vector<Vec<2>> x = {Vec<2>(kLx / 2 - 1e-4, -kLy / 2 + 3e-4),
                                 Vec<2>(-kLx / 2 + 1e-4, -kLy / 2 + 3e-4)};
  const std::vector<Vec<2>> v = {Vec<2>(0.01, 0), Vec<2>(0.01, 0)};
  GhostSet<2> G;
  GhostOptions<2> opt;
  opt.map = GhostMapKind::mirror_beta;
  opt.velocity = GhostVelocity::no_slip;
  opt.support = support;
  opt.cells = &cells;
  G.build(x, v, walls, opt);
  ASSERT_EQ(G.size(), 2u);  // the top wall is 9.7 mm away
  EXPECT_TRUE(G.penetrated.empty());
  for (std::size_t g = 0; g < 2; ++g) {
    EXPECT_EQ(G.wall[g], 0);
    EXPECT_NEAR(G.x[g].y(), -kLy / 2 - 3e-4, 1e-12);
    EXPECT_NEAR(G.x[g].x(), x[G.source[g]].x(), 1e-12);
    EXPECT_NEAR(G.beta[g], 1.0, 1e-12);
    EXPECT_NEAR(G.v[g].x(), -0.01, 1e-12);  // no slip: -u across a resting wall
  }
  CellList<2> gcells;
  gcells.configure(support, c.domain_min, c.domain_max, c.periodic);
  gcells.build(G.x);
  for (std::size_t i = 0; i < 2; ++i) {
    int seen = 0;
    gcells.for_each_neighbor(x[i], G.x, [&](Index, const Vec<2>&, Real) { ++seen; });
    EXPECT_EQ(seen, 2) << "particle " << i;
  }
}

TEST(ThrottledPipeRun, ShortCoarseRunStaysInsideWithFiniteFlux) {
  // From rest, so the flux comes from the body force alone.
  const Case c = read_case(kCase, {"resolution.dx=5e-4", "time.end=0.03", "output.vtk=false",
                                   "initial.throttled_pipe.velocity=rest"});
  Solver<2> solver(c);
  solver.initialize();
  const auto& P = solver.particles();
  ASSERT_GT(P.size(), 500u);
  while (solver.time() < c.t_end) solver.step(static_cast<Real>(c.t_end - solver.time()));
  ASSERT_GT(solver.steps(), 100);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const WallPoint<2> p = solver.walls().closest(P.x[i].cast<double>());
    ASSERT_GT(p.distance, 0.0) << "particle " << P.id[i];
    ASSERT_GE(P.x[i].x(), -kLx / 2);
    ASSERT_LT(P.x[i].x(), kLx / 2);
  }
  auto a = make_analysis<2>("throttled_pipe", c.root["analysis"]["throttled_pipe"], c);
  nlohmann::json m;
  a->finish(solver.time(), P, m, {});
  const double fv = m["flux_variation"], q = m["flux_mean"];
  EXPECT_TRUE(std::isfinite(fv));
  EXPECT_GE(fv, 0.0);
  EXPECT_GT(q, 0.0);  // the body force pushes along +x
  EXPECT_TRUE(std::isfinite(m["centerline_vx_rel_error"].get<double>()));
  EXPECT_NEAR(m["throat_half_width"].get<double>(), kLy / 4, 1e-12);
}

TEST(ThrottledPipeInitial, WallFittedColumnsLeaveNoDensityHoles) {
  // The clipped lattice of `inside_walls` starts at 0.72 rho0 next to the bump; the
  // wall-fitted columns keep the summation density within 3 % of rho0 (dx = 5e-4: 0.978 ..
  // 1.017), and the lubrication start carries the flux it was built for. At h = 1.3 dx (the
  // case's h = 2.5 dx smooths the sections' interpolated profiles by ~1.5 sigma^2/R^2: -4 % at
  // dx = 5e-4, which the particle flux sum below does not have).
  const Case c = read_case(
      kCase, {"resolution.dx=5e-4", "resolution.h_over_dx=1.3", "density.method=summation"});
  Solver<2> solver(c);
  solver.initialize();
  const auto& P = solver.particles();
  double lo = 1e300, hi = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    lo = std::min(lo, static_cast<double>(P.rho[i]));
    hi = std::max(hi, static_cast<double>(P.rho[i]));
  }
  EXPECT_GT(lo, 0.97 * 1000.0);
  EXPECT_LT(hi, 1.04 * 1000.0);
  // Away from the walls the summation density starts at rho0 itself: the masses are rho0 over
  // the column lattice's node density (rho0 cx dy started it at 1010.5, a pressure ~11 Pa
  // above p0).
  std::vector<double> rho(P.rho.begin(), P.rho.end());
  std::nth_element(rho.begin(), rho.begin() + static_cast<long>(rho.size() / 2), rho.end());
  EXPECT_NEAR(rho[rho.size() / 2], 1000.0, 0.5);
  auto a = make_analysis<2>("throttled_pipe", c.root["analysis"]["throttled_pipe"], c);
  nlohmann::json m;
  a->finish(0.0, P, m, {});
  EXPECT_LT(m["flux_variation"].get<double>(), 0.03);
  // The case starts at its reference flux (the lubrication profile carrying Q_ref).
  const double q0 = c.root["initial"]["throttled_pipe"]["flux"].as<double>();
  EXPECT_NEAR(m["reynolds"].get<double>(), 1000.0 * q0 / 0.01, 1.0);
  EXPECT_NEAR(m["flux_rel_error"].get<double>(), 0.0, 0.02);
  // sum V v_x / L_x over the particles is the integral of the lubrication profile over the
  // fluid, which carries q0 at every section, to the columns' midpoint rule and the summation
  // density's 2-3 % near the walls (V = m / rho): -0.8 % here.
  EXPECT_NEAR(m["flux_particles_rel_error"].get<double>(), 0.0, 0.01);
}

TEST(ThrottledPipeAnalysis, RejectsTooFewSections) {
  const Case c = read_case(kCase, {"analysis.throttled_pipe.sections=10"});
  EXPECT_ANY_THROW(make_analysis<2>("throttled_pipe", c.root["analysis"]["throttled_pipe"], c));
}

}  // namespace
}  // namespace curvsph
