// The run's first-density-sum diagnostic (Solver::initial_density_error, `density_error_initial`
// in metrics.json) on a channel whose lattice is not centred between its plane walls: the
// rows sit 1.15 dx above the floor and 0.85 dx below the lid, so the mirror ghosts leave gaps
// there. Reference: the summation density by brute force over the lattice rows and their
// mirror images, with the Wendland C2 kernel written out (Barker eq. 5, 2-D constant
// 7 / (4 pi h^2)), independent of the solver's cell lists and ghost code.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "../support/quiet_run.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"

namespace curvsph {
namespace {

nlohmann::json run_setup_only(const char* yaml, const std::string& name) {
  return test::run_quiet(read_case(YAML::Load(yaml), name));
}

TEST(InitialDensityError, MatchesBruteForceLatticeAndImageSums) {
  const double dx = 0.01, h = 1.5 * dx, lx = 0.1, ly = 0.1, rho0 = 1000;
  const auto m = run_setup_only(R"(
name: offset_channel
dimension: 2
resolution: {dx: 0.01, h_over_dx: 1.5}
domain: {min: [0, -0.0035], max: [0.1, 0.1], periodic: [true, false]}
fluids:
  - {name: water, rho0: 1000, viscosity: 1.0e-3,
     region: {box: {min: [0, -0.0035], max: [0.1, 0.1]}}}
eos: {type: tait, c0: 1.0, gamma: 7, p0: 1.0}
density: {method: summation}
walls:
  - {shape: plane, point: [0, 0], normal: [0, 1]}
  - {shape: plane, point: [0, 0.1], normal: [0, -1]}
boundary: {method: ghost, map: mirror, velocity: no_slip}
time: {end: 0}
output: {vtk: false}
)",
                                "offset_channel.yaml");

  // Lattice of the region box: x = (i + 1/2) dx, y = -0.0035 + (k + 1/2) dx below ly, points
  // closer than 0.3 dx to a wall dropped (README): rows at 0.0115 ... 0.0915.
  std::vector<double> rows;
  for (int k = 0;; ++k) {
    const double y = -0.0035 + (k + 0.5) * dx;
    if (y >= ly) break;
    if (y > 0.3 * dx && ly - y > 0.3 * dx) rows.push_back(y);
  }
  ASSERT_EQ(rows.size(), 9u);
  ASSERT_NEAR(rows.front(), 0.0115, 1e-12);
  const double support = 2 * h;
  auto W = [&](double r) {
    const double q = r / h;
    if (q >= 2) return 0.0;
    return 7.0 / (4 * std::numbers::pi * h * h) * std::pow(1 - q / 2, 4) * (1 + 2 * q);
  };
  // Every source row (and its images within 2h of a wall) as y positions; x is periodic.
  std::vector<double> sources = rows;
  for (double y : rows) {
    if (y < support) sources.push_back(-y);               // floor image
    if (ly - y < support) sources.push_back(2 * ly - y);  // lid image
  }
  const int nx = static_cast<int>(std::lround(lx / dx));
  double max_err = 0, mean = 0;
  std::vector<double> q(rows.size());
  for (std::size_t a = 0; a < rows.size(); ++a) {
    double sigma = 0;
    for (double ys : sources)
      for (int i = -nx; i <= nx; ++i) sigma += W(std::hypot(i * dx, rows[a] - ys));
    q[a] = rho0 * dx * dx * sigma / rho0;  // m = rho0 dx^2; rho / rho_set
    max_err = std::max(max_err, std::abs(q[a] - 1));
    mean += q[a] / rows.size();  // every row holds nx particles
  }
  double local = 0;
  long above = 0;
  for (double v : q) {
    local = std::max(local, std::abs(v / mean - 1));
    above += std::abs(v / mean - 1) > 0.01 ? nx : 0;
  }
  EXPECT_NEAR(m["density_error_initial"].get<double>(), max_err, 1e-9);
  EXPECT_NEAR(m["density_error_initial_local"].get<double>(), local, 1e-9);
  EXPECT_EQ(m["density_error_initial_local_above_1pct"].get<long>(), above);
  EXPECT_GT(local, 0.05);  // the 2.3 dx gap at the floor is a large local error
}

TEST(InitialDensityError, AbsentWithContinuityDensity) {
  const auto m = run_setup_only(R"(
name: box
dimension: 2
resolution: {dx: 0.01, h_over_dx: 1.5}
domain: {min: [0, 0], max: [0.1, 0.1], periodic: [true, true]}
fluids:
  - {name: water, rho0: 1000, viscosity: 1.0e-3, region: {box: {min: [0, 0], max: [0.1, 0.1]}}}
eos: {type: tait, c0: 1.0, gamma: 7, p0: 0}
density: {method: continuity}
time: {end: 0}
output: {vtk: false}
)",
                                "box.yaml");
  EXPECT_FALSE(m.contains("density_error_initial"));
}

}  // namespace
}  // namespace curvsph
