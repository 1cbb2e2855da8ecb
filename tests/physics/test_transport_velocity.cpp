// Transport-velocity formulation (physics/transport_velocity.hpp, Adami, Hu & Adams 2013).
// References: a central difference of the kernel sum (the background push is minus its
// gradient), the analytic divergence of A = rho u (u~ - u) for a smooth field, momentum
// conservation of the pair term, and the Taylor–Green vortex's analytic decay.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "../support/lattice.hpp"
#include "../support/quiet_run.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/physics/transport_velocity.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

constexpr double kPi = std::numbers::pi;

// b of every particle of a lattice for background pressure pb.
template <int D>
std::vector<Vec<D>> background_push(test::Lattice<D>& L, Real pb) {
  TransportVelocity<D> tv;
  tv.background_pressure = pb;
  shift_sums(L.P, L.cells, L.W, static_cast<Real>(L.dx), tv.sums);
  transport_acceleration(L.P, static_cast<Index>(L.P.size()), tv);
  return tv.b;
}

TEST(TransportVelocity, BackgroundPushIsMinusTheGradientOfTheKernelSum) {
  test::Lattice<2> L(32, 1.5, 0.2);  // jittered: b != 0
  const Real pb = 100;
  const auto b = background_push(L, pb);
  // -(2 pb / rho_i) grad_x sum_{j != i} V_j W(|x - x_j|) at x = x_i, by central differences of a
  // brute-force sum over every particle (minimal image).
  const double eps = 1e-6;
  double worst = 0, scale = 0;
  for (Index i : {3, 100, 517, 1000}) {
    auto S = [&](const Vec<2>& x) {
      double s = 0;
      for (std::size_t j = 0; j < L.P.size(); ++j)
        if (static_cast<Index>(j) != i)
          s += L.P.mass[j] / L.P.rho[j] * L.W.value(L.cells.separation(x, L.P.x[j]).norm());
      return s;
    };
    Vec<2> ref;
    for (int d = 0; d < 2; ++d) {
      Vec<2> e = Vec<2>::Zero();
      e[d] = static_cast<Real>(eps);
      ref[d] = -(2 * pb / L.P.rho[i]) * (S(L.P.x[i] + e) - S(L.P.x[i] - e)) / (2 * eps);
    }
    worst = std::max(worst, static_cast<double>((b[static_cast<std::size_t>(i)] - ref).norm()));
    scale = std::max(scale, static_cast<double>(ref.norm()));
  }
  EXPECT_GT(scale, 10.0);  // a jittered lattice is pushed (units: Pa / (kg/m^3) / m)
  EXPECT_LT(worst, 1e-5 * scale);

  test::Lattice<2> uniform(32, 1.5, 0.0);
  double most = 0;
  for (const auto& v : background_push(uniform, pb)) most = std::max(most, double(v.norm()));
  EXPECT_LT(most, 1e-9 * scale);  // nothing to regularise on the lattice
}

TEST(TransportVelocity, StressTermIsTheDivergenceOfA) {
  // u = (sin 2 pi x, 0), u~ - u = (d, 0): A = rho u (x) (u~ - u) has div A = (2 pi d cos 2 pi x, 0)
  // at rho = 1.
  test::Lattice<2> L(64, 2.0, 0.0);
  TransportVelocity<2> tv;
  tv.background_pressure = 1;
  const Real d = Real(0.01);
  tv.du.assign(L.P.size(), Vec<2>(d, 0));
  for (std::size_t i = 0; i < L.P.size(); ++i) {
    L.P.v[i] = Vec<2>(std::sin(2 * kPi * L.P.x[i].x()), 0);
    L.P.a[i].setZero();
  }
  std::vector<Vec<2>> scratch;
  add_transport_stress(L.P, L.cells, L.W, tv, scratch);
  double err2 = 0, ref2 = 0;
  for (std::size_t i = 0; i < L.P.size(); ++i) {
    const Vec<2> ref(2 * kPi * d * std::cos(2 * kPi * L.P.x[i].x()), 0);
    err2 += (L.P.a[i] - ref).squaredNorm();
    ref2 += ref.squaredNorm();
  }
  EXPECT_LT(std::sqrt(err2 / ref2), 0.01);
}

TEST(TransportVelocity, StressTermConservesMomentum) {
  test::Lattice<2> L(24, 1.5, 0.3);
  L.randomize_state(11);
  TransportVelocity<2> tv;
  tv.background_pressure = 1;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  tv.du.resize(L.P.size());
  for (auto& v : tv.du) v = Vec<2>(U(rng), U(rng));
  for (auto& a : L.P.a) a.setZero();
  std::vector<Vec<2>> scratch;
  add_transport_stress(L.P, L.cells, L.W, tv, scratch);
  Vec<2> total = Vec<2>::Zero();
  double size = 0;
  for (std::size_t i = 0; i < L.P.size(); ++i) {
    total += L.P.mass[i] * L.P.a[i];
    size += L.P.mass[i] * L.P.a[i].norm();
  }
  EXPECT_GT(size, 0);
  EXPECT_LT(total.norm(), 1e-12 * size);
}

// cases/taylor_green_2d.yaml at dx = 0.02 with summation density; `tvf` adds the transport
// velocity (p_b = rho0 c0^2 = 100) with p0 = 0, the other keeps the case's p0 = 5.
nlohmann::json taylor_green(bool tvf) {
  YAML::Node root = YAML::LoadFile(std::string(CURVSPH_SOURCE_DIR) + "/cases/taylor_green_2d.yaml");
  root["resolution"]["dx"] = 0.02;
  root["density"] = YAML::Load("{method: summation}");
  root["time"]["end"] = 0.5;
  root["output"] = YAML::Load("{vtk: false}");
  root.remove("probes");
  if (tvf) {
    root["eos"]["p0"] = 0;
    root["transport_velocity"] = YAML::Load("{}");
  }
  const Case c = read_case(root, "taylor_green_tvf");
  EXPECT_NEAR(c.transport_pb, tvf ? 100.0 : 0.0, 1e-12);  // default: rho0 c0^2
  return test::run_quiet(c, 1);
}

TEST(TransportVelocity, TaylorGreenFollowsTheAnalyticDecay) {
  // Kinetic energy ratio exp(-16 pi^2 nu t), nu = 0.01, t = 0.5, computed here.
  const double exact = std::exp(-16 * kPi * kPi * 0.01 * 0.5);
  const auto with = taylor_green(true);
  const auto without = taylor_green(false);
  EXPECT_NEAR(with["kinetic_energy_ratio_reference"].get<double>(), exact, 1e-12);
  const double e_with = std::abs(with["kinetic_energy_ratio"].get<double>() / exact - 1);
  const double e_without = std::abs(without["kinetic_energy_ratio"].get<double>() / exact - 1);
  EXPECT_LT(e_with, 0.02);
  EXPECT_LT(with["l2_velocity_error"].get<double>(), 0.05);
  // Summation density with a background pressure and nothing else decays too fast (the
  // particles clump at the stagnation points): the transport velocity is what keeps it right.
  EXPECT_GT(e_without, 3 * e_with);
}

TEST(TransportVelocity, CaseKeysAreChecked) {
  auto load = [](const std::string& density, const std::string& tv) {
    YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.1}
fluids: [{rho0: 1000, region: {box: {min: [0, 0], max: [1, 1]}}}]
eos: {type: tait, c0: 2, p0: 0}
time: {end: 1}
)");
    root["density"] = YAML::Load(density);
    root["transport_velocity"] = YAML::Load(tv);
    return read_case(root, "dir/case.yaml");
  };
  EXPECT_NEAR(load("{method: summation}", "{}").transport_pb, 4000.0, 1e-9);
  EXPECT_NEAR(load("{method: summation}", "{background_pressure: 50}").transport_pb, 50.0, 1e-12);
  auto expect_refused = [&](const std::string& density, const std::string& tv,
                            const std::string& key, const std::string& reason) {
    try {
      load(density, tv);
      ADD_FAILURE() << "no error for " << density << " " << tv;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
      EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
    }
  };
  expect_refused("{method: continuity}", "{}", "transport_velocity", "summation");
  expect_refused("{method: summation, shifting: 0.02}", "{}", "transport_velocity", "shifting");
  expect_refused("{method: summation}", "{background_pressure: -1}",
                 "transport_velocity.background_pressure", "> 0");
  expect_refused("{method: summation}", "{pb: 1}", "transport_velocity.pb", "unknown key");
}

}  // namespace
}  // namespace curvsph
