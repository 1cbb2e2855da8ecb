// The delta-SPH diffusive term's forms (physics/density.hpp, DensityDiffusion):
//  - the symmetric continuity pass with the Fourtakas hydrostatic part against an N^2
//    brute force written from the definition rho^T_ji = (rho_j - rho^H_j) - (rho_i - rho^H_i)
//    (each ordered pair, vector form of psi; the pass takes each pair once, scalar form);
//  - a hydrostatic block at rest (open lattice, linear EOS, the exact exponential profile
//    rho = rho0 exp(g (H - z) / c0^2)): the Fourtakas term vanishes to O(|g.r/c0^2|^3) at
//    every particle, free surface and block edges included, where the Molteni term does not;
//  - the case keys (density.diffusion_term) and their refusals.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <vector>

#include "../support/lattice.hpp"
#include "../support/solver_refusal.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/physics/density.hpp"
#include "curvsph/physics/fluid_terms.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

// Open grid over the unit box: a hydrostatic field is not periodic.
template <int D>
void make_open(test::Lattice<D>& L) {
  L.cells.configure(L.W.support, Vec3d::Zero(), Vec3d::Ones(), {false, false, false});
  L.cells.build(L.P.x);
}

template <int D>
void check_fourtakas_brute_force() {
  test::Lattice<D> L(D == 2 ? 24 : 9, 1.6, 0.3, 11);
  make_open(L);
  L.randomize_state(5);
  auto& P = L.P;
  const Real c0 = 3;
  Vec<D> g = Vec<D>::Zero();
  g[D - 1] = -9.81;
  g[0] = 2.5;  // any direction: the term only sees g.r
  const Vec<D> k = g / (c0 * c0);
  const Real dhc = 0.1 * L.W.h * c0;
  // rho^H_j - rho^H_i: the pair's mean density times g.(x_j - x_i) / c0^2, written with
  // x_j - x_i (the pass uses -r_ij) and the vector form of psi below (the pass: scalars).
  auto rho_h_diff = [&](std::size_t i, std::size_t j) {
    return (L.P.rho[i] + L.P.rho[j]) / 2 * g.dot(L.P.x[j] - L.P.x[i]) / (c0 * c0);
  };

  const std::size_t n = P.size();
  std::vector<Real> ref(n, 0);
  double scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Real div = 0, diff = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const Vec<D> r = P.x[i] - P.x[j];
      const Real q = r.norm();
      if (j == i || q >= L.W.support) continue;
      const Vec<D> gradW = r * L.W.gradient_factor(q);
      const Real Vj = P.mass[j] / P.rho[j];
      div += Vj * (P.v[i] - P.v[j]).dot(gradW);
      const Real rho_t = P.rho[j] - P.rho[i] - rho_h_diff(i, j);
      diff += Vj * (2 * rho_t * (-r) / (q * q)).dot(gradW);
    }
    ref[i] = P.rho[i] * div + dhc * diff;
    scale = std::max(scale, std::abs(ref[i]));
  }
  PairFactors<D> pf;
  continuity_rate(P, L.cells, L.W, DensityDiffusion<D>{dhc, nullptr, k}, pf);
  double err = 0;
  for (std::size_t i = 0; i < n; ++i) err = std::max(err, std::abs(P.drho[i] - ref[i]) / scale);
  EXPECT_LT(err, 1e-12);
  // The hydrostatic part is not negligible here: without it the rate differs at O(1).
  continuity_rate(P, L.cells, L.W, DensityDiffusion<D>{dhc, nullptr, Vec<D>::Zero()}, pf);
  double diff_molteni = 0;
  for (std::size_t i = 0; i < n; ++i)
    diff_molteni = std::max(diff_molteni, std::abs(P.drho[i] - ref[i]) / scale);
  EXPECT_GT(diff_molteni, 1e-3);
}

TEST(DensityDiffusion, FourtakasMatchesBruteForce2D) {
  check_fourtakas_brute_force<2>();
}
TEST(DensityDiffusion, FourtakasMatchesBruteForce3D) {
  check_fourtakas_brute_force<3>();
}

// A block of fluid at rest in the lower part of the unit box (its top row is a free surface,
// its sides and bottom end without walls), with the hydrostatic density of the linear EOS:
// rho_i = rho0 (1 + g (H - z_i) / c0^2). Max |drho/dt| over every particle, per form.
template <int D>
double hydrostatic_rate(bool fourtakas) {
  test::Lattice<D> L(D == 2 ? 30 : 12, 2.0, 0.0);
  auto& P = L.P;
  const Real rho0 = 1000, c0 = 20, g = 9.81, H = 1;
  FluidParams<D> F;
  F.rho0 = {rho0};
  F.eos.type = Eos::Type::linear;
  F.eos.c0 = c0;
  F.gravity[D - 1] = -g;
  F.diffusion =
      fourtakas ? FluidParams<D>::Diffusion::fourtakas : FluidParams<D>::Diffusion::molteni;
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.rho[i] = rho0 * std::exp(g * (H - P.x[i][D - 1]) / (c0 * c0));
    P.mass[i] = rho0 * std::pow(L.dx, D);
    P.v[i].setZero();
  }
  make_open(L);
  PairFactors<D> pf;
  const DensityDiffusion<D> dd{Real(0.1) * L.W.h * c0, nullptr, F.hydrostatic_density_gradient()};
  continuity_rate(P, L.cells, L.W, dd, pf);
  double m = 0;
  for (std::size_t i = 0; i < P.size(); ++i) m = std::max(m, std::abs(P.drho[i]));
  return m;
}

template <int D>
void check_hydrostatic_steady() {
  const double fourtakas = hydrostatic_rate<D>(true);
  const double molteni = hydrostatic_rate<D>(false);
  // Molteni diffuses the hydrostatic profile where the stencil is one-sided (top and bottom
  // rows): rate ~ delta h c0 (rho0 g / c0^2) / h. Fourtakas with the pair's mean density:
  // the trapezoid error of the exponential, (k.r)^2 / 12 ~ 1e-6 of that (the paper's rho0 in
  // place of rho_ij leaves (rho - rho0)/rho0 ~ g H / c0^2 = 2.5e-2 of it).
  EXPECT_GT(molteni, 1e-3);
  EXPECT_LT(fourtakas, 1e-5 * molteni);
}

TEST(DensityDiffusion, FourtakasKeepsHydrostaticBlockSteady2D) {
  check_hydrostatic_steady<2>();
}
TEST(DensityDiffusion, FourtakasKeepsHydrostaticBlockSteady3D) {
  check_hydrostatic_steady<3>();
}

YAML::Node small_case() {
  return YAML::Load(R"(
name: t
dimension: 2
resolution: {dx: 0.05, h_over_dx: 2}
domain: {min: [0, 0], max: [1, 1], periodic: [true, false]}
fluids:
  - {name: water, rho0: 1000, viscosity: 0.001, region: {box: {min: [0, 0], max: [1, 0.5]}}}
eos: {type: linear, c0: 20}
density: {method: continuity, delta_sph: 0.1, diffusion_term: fourtakas}
gravity: [0, -9.81]
time: {end: 0.01}
)");
}

std::string refusal(const YAML::Node& root) {
  return test::solver_refusal<2>(root);
}

TEST(DensityDiffusion, CaseKeys) {
  const Case c = read_case(small_case(), "case.yaml");
  EXPECT_EQ(c.density.diffusion, DensitySpec::Diffusion::fourtakas);
  EXPECT_EQ(refusal(small_case()), "");

  YAML::Node r = small_case();
  r["density"]["diffusion_term"] = "marrone";
  EXPECT_NE(refusal(r).find("density.diffusion_term"), std::string::npos) << refusal(r);

  r = small_case();
  r["density"] = YAML::Load("{method: summation, diffusion_term: molteni}");
  EXPECT_NE(refusal(r).find("only applies to method: continuity"), std::string::npos) << refusal(r);

  r = small_case();
  r["gravity"] = YAML::Load("[1.0, -9.81]");  // along the periodic x axis
  EXPECT_NE(refusal(r).find("periodic axis 0"), std::string::npos) << refusal(r);
}

}  // namespace
}  // namespace curvsph
