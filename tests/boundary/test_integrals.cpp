// Boundary integrals as a boundary model (boundary.method: integrals): the per-particle
// Shepard factor of the solver matches shepard_geometric() evaluated directly, periodic
// images included, and a tiny hydrostatic tank stays at rest with a hydrostatic pressure.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>

#include "../support/bi_tank.hpp"
#include "../support/quiet_run.hpp"
#include "curvsph/boundary/integrals/integrals_boundary.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/core/quadrature.hpp"
#include "curvsph/geometry/box.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

YAML::Node tank(const std::string& shepard) {
  return test::bi_tank(shepard);
}

TEST(IntegralsBoundary, GammaMatchesGeometricShepardOnTankLattice) {
  const Case c = read_case(tank("geometric"), "integrals_test");
  Solver<2> s(c);
  s.initialize();
  const auto* bi = dynamic_cast<const IntegralsBoundary<2>*>(s.boundary());
  ASSERT_NE(bi, nullptr);
  const auto& P = s.particles();
  ASSERT_EQ(P.size(), 300u);
  const auto el = elements_from_walls<2>(s.walls(), c.dx, Bounds<2>(Vec2d(-1, -1), Vec2d(1, 1)));
  ASSERT_EQ(bi->gamma().size(), P.size());
  int reduced = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double ref = shepard_geometric<2>(el, P.x[i].cast<double>(), c.h());
    EXPECT_NEAR(bi->gamma()[i], ref, 1e-12) << "particle at " << P.x[i].transpose();
    if (ref < 0.999) ++reduced;
  }
  EXPECT_GT(reduced, 100);  // the first rows along three walls see them
}

TEST(IntegralsBoundary, GammaWithPeriodicImagesMatchesDirectSum) {
  // A channel periodic in x: the floor's elements are seen through the periodic image near
  // x = 0 and x = L; gamma must be the same at both ends.
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.01, h_over_dx: 2}
domain: {min: [0, 0], max: [0.2, 0.1], periodic: [true, false]}
fluids: [{rho0: 1, viscosity: 0.01, region: {box: {min: [0, 0], max: [0.2, 0.1]}}}]
eos: {type: linear, c0: 1, p0: 0}
walls: [{shape: plane, point: [0, 0], normal: [0, 1]}, {shape: plane, point: [0, 0.1], normal: [0, -1]}]
boundary: {method: integrals, shepard: geometric}
time: {end: 1.0}
)");
  const Case c = read_case(root, "integrals_periodic_test");
  Solver<2> s(c);
  s.initialize();
  const auto* bi = dynamic_cast<const IntegralsBoundary<2>*>(s.boundary());
  ASSERT_NE(bi, nullptr);
  const auto& P = s.particles();
  // Reference: the same walls as infinite lines (elements over a wide box).
  const auto el =
      elements_from_walls<2>(s.walls(), c.dx, Bounds<2>(Vec2d(-1, -0.5), Vec2d(1.2, 0.6)));
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double ref = shepard_geometric<2>(el, P.x[i].cast<double>(), c.h());
    EXPECT_NEAR(bi->gamma()[i], ref, 1e-8) << "particle at " << P.x[i].transpose();
  }
}

TEST(IntegralsBoundary, TinyHydrostaticTankStaysAtRest) {
  const Case c = read_case(tank("geometric"), "integrals_test");
  const auto m = test::run_quiet(c);
  EXPECT_EQ(m["steps"].get<long>(), 300);
  EXPECT_EQ(m["escaped_particles"].get<long>(), 0);
  // Bounded kinetic energy; the pressure rings acoustically after the start (the discrete
  // BI identity holds to a few % at h/dx = 2, integrals_boundary.cpp item 2b). Measured after
  // these 300 steps (t sqrt(g/H) = 1.24): KE max 6.0e-5 M g H, pressure error 0.035 of
  // rho0 g H; the bounds leave a margin for other compilers. This checks the start-up only:
  // run on to 3000 steps (t sqrt(g/H) = 12.4) this 12-row tank does not stay at rest (KE
  // max 1.3e-4 to 4.9e-4, pressure error 0.24-0.30 at the end, depending on the output
  // times that cut the steps; issue 5).
  EXPECT_LT(m["kinetic_energy_max"].get<double>(), 1e-4);
  EXPECT_LT(m["pressure_l2_error"].get<double>(), 0.05);
}

TEST(IntegralsBoundary, HydrostaticInitialFieldIsTheCompressibleBalance) {
  // `initial: hydrostatic` solves dp/dz = rho(p) g; with the linear EOS rho = rho0 + p/c0^2
  // that is p = rho0 c0^2 (exp(g z/c0^2) - 1) (analytic), and the bulk particles of the
  // lattice then start in balance: the SPH pressure gradient cancels gravity to the lattice's
  // moment error (~1e-3 g), where p = rho0 g z left 1 % of g at the bottom.
  const Case c = read_case(tank("geometric"), "integrals_test");
  Solver<2> s(c);
  s.initialize();
  const auto& P = s.particles();
  const double rho0 = 998, g = 9.81, c0 = 6.9, H = 0.048, h = c.h();
  int bulk = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double z = H - P.x[i][1];
    const double ref = rho0 * c0 * c0 * std::expm1(g * z / (c0 * c0));
    EXPECT_NEAR(P.p[i], ref, 1e-5 * rho0 * g * H) << "particle at " << P.x[i].transpose();
    const double x = P.x[i][0], y = P.x[i][1];
    if (x > 2 * h && x < 0.1 - 2 * h && y > 2 * h && z > 2 * h) {
      ++bulk;
      EXPECT_LT(P.a[i].norm(), 2e-3 * g) << "particle at " << P.x[i].transpose();
    }
  }
  EXPECT_GT(bulk, 20);
}

TEST(IntegralsBoundary, WallForceKeyIsParsed) {
  YAML::Node root = tank("geometric");
  root["boundary"]["wall_force"] = true;
  EXPECT_TRUE(read_case(root, "integrals_test").boundary.wall_force);
  EXPECT_FALSE(read_case(tank("geometric"), "integrals_test").boundary.wall_force);
}

}  // namespace
}  // namespace curvsph

namespace curvsph {
namespace {

// Brute force R_i = sum_j V_j grad_i W_ij - sum_b (int_b W dS) n_b over every particle and
// element (no cell lists), each straight element integrated by the 2-point Gauss rule written
// out (what the packing uses, element_quadrature.hpp) or, with `reference`, by 8-point
// Gauss-Legendre on 4 pieces.
Vec2 brute_residual(const std::vector<Vec2>& x, std::size_t i, const BoundaryElements<2>& el,
                    const WendlandC2<2>& W, double V, bool reference = false) {
  Vec2 g = Vec2::Zero();
  for (std::size_t j = 0; j < x.size(); ++j) {
    if (j == i) continue;
    const Vec2 r = x[i] - x[j];
    g += V * W.gradient_factor(r.norm()) * r;
  }
  for (std::size_t b = 0; b < el.size(); ++b) {
    const Vec2d a = el.vertices[b][0], e = el.vertices[b][1];
    const auto w = [&](double u) {
      const Vec2d y = a + u * (e - a);
      return static_cast<double>(W.value((x[i] - y.cast<Real>()).norm()));
    };
    const double k = 0.5 / std::sqrt(3.0);
    const double mean = reference ? gauss_legendre_8(w, 0, 1, 4) : 0.5 * (w(0.5 - k) + w(0.5 + k));
    g -= static_cast<Real>(mean * (e - a).norm()) * el.normal[b].cast<Real>();
  }
  return g;
}

TEST(IntegralsPacking, ResidualReducedAndMatchesBruteForce) {
  // setup.relax.map: integrals on the tiny tank: the residual the packing reports is the
  // brute-force R_i against the fluid region's box closure, before (bare lattice: a few % of
  // sum_b W n A on the wall rows) and after packing to 1e-5.
  YAML::Node root = tank("geometric");
  root["setup"] = YAML::Load("{relax: {map: integrals, max_steps: 3000, tolerance: 1.0e-5}}");
  const Case c = read_case(root, "integrals_test");
  Solver<2> s(c);
  ASSERT_TRUE(s.relax_result().has_value());
  EXPECT_LT(s.relax_result()->spread, 1e-5);
  const auto& P = s.particles();
  const WendlandC2<2> W(static_cast<Real>(c.h()));
  const BoxWall<2> closure(Vec2d(0, 0), Vec2d(0.1, 0.048), FluidSide::inside);
  const auto el = elements_from_wall<2>(closure, c.dx, Bounds<2>(Vec2d(-1, -1), Vec2d(1, 1)));
  const double V = c.dx * c.dx;
  double worst = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    worst = std::max(worst, c.h() * brute_residual(P.x, i, el, W, V).norm());
  EXPECT_NEAR(worst, s.relax_result()->spread, 1e-9);
  // Against the element integrals themselves: the 2-point rule's error (measured 2.3e-4).
  double exact = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    exact = std::max(exact, c.h() * brute_residual(P.x, i, el, W, V, true).norm());
  EXPECT_LT(exact, 5e-4);
  const Case c0 = read_case(tank("geometric"), "integrals_test");
  Solver<2> s0(c0);
  double bare = 0;
  for (std::size_t i = 0; i < s0.particles().size(); ++i)
    bare = std::max(bare, c.h() * brute_residual(s0.particles().x, i, el, W, V).norm());
  EXPECT_NEAR(bare, s.relax_result()->spread_initial, 1e-9);
  EXPECT_GT(bare, 1e-2);
}

TEST(IntegralsPacking, ReachesItsToleranceAtTheCorners) {
  // With W_ib at the element centres the wall sum has a curl at the box corners and the
  // descent stalled there (this tank: max h|R| 7.1e-4 at h/dx = 2 and 6.6e-4 at h/dx = 3
  // after 4000 steps, never below 1e-4); with the element quadrature it reaches 1e-4 in
  // ~100 steps (98 and 93 measured).
  for (const char* h_over_dx : {"2", "3"}) {
    YAML::Node root = tank("geometric");
    root["resolution"]["h_over_dx"] = h_over_dx;
    root["setup"] = YAML::Load("{relax: {map: integrals, max_steps: 1000, tolerance: 1.0e-4}}");
    Solver<2> s(read_case(root, "integrals_test"));
    ASSERT_TRUE(s.relax_result().has_value());
    EXPECT_LT(s.relax_result()->spread, 1e-4) << "h/dx = " << h_over_dx;
    EXPECT_LT(s.relax_result()->steps, 300) << "h/dx = " << h_over_dx;
  }
}

TEST(IntegralsPacking, PackedWallRowsStartInBalance) {
  // Hydrostatic equilibrium means a = 0 (analytic). On the bare lattice the symmetric BI
  // pressure term leaves 2 p_i R_i / (gamma_i rho_i) on the wall rows (measured on the
  // 0.5 m tank: -1.76 g on the first floor row; here, 12 rows deep, up to 0.4 g at the
  // bottom corners). After packing, the particles below the free surface's reach (y < H - 2h)
  // start within 0.05 g of balance. (At the free surface, where the packing's temporary lid is
  // gone, up to 0.2 g remain near the contact lines: p_i is small there.)
  auto worst_below = [](const Solver<2>& s, double ymax) {
    double w = 0;
    for (std::size_t i = 0; i < s.particles().size(); ++i)
      if (s.particles().x[i][1] < ymax) w = std::max(w, double(s.particles().a[i].norm()));
    return w;
  };
  YAML::Node root = tank("geometric");
  root["setup"] = YAML::Load("{relax: {map: integrals, max_steps: 1000, tolerance: 1.0e-5}}");
  const Case c = read_case(root, "integrals_test");
  Solver<2> s(c);
  s.initialize();
  const double ymax = 0.048 - 2 * c.h();
  EXPECT_LT(worst_below(s, ymax), 0.05 * 9.81);
  Solver<2> s0(read_case(tank("geometric"), "integrals_test"));
  s0.initialize();
  EXPECT_GT(worst_below(s0, ymax), 0.2 * 9.81);
}

TEST(IntegralsPacking, NeedsOneBoxRegion) {
  YAML::Node root = tank("geometric");
  root["setup"] = YAML::Load("{relax: {map: integrals}}");
  root["fluids"][0]["region"] = YAML::Load("{disk: {center: [0.05, 0.02], radius: 0.015}}");
  EXPECT_THROW(Solver<2>(read_case(root, "integrals_test")), InputError);
}

}  // namespace
}  // namespace curvsph
