// The surge-front analysis (analysis/surge_front.hpp) on synthetic particle sets whose front
// moves by a known law: the reduced fronts Z(T) it records (wet floor, largest x), their relative
// errors against a CSV "experiment" written for the test, the lag and the front speeds, computed
// by hand here.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "curvsph/analysis/analysis.hpp"
#include "curvsph/io/case_file.hpp"

namespace curvsph {
namespace {

TEST(SurgeFront, FrontOnTheFloorAgainstTheExperiment) {
  const auto dir = std::filesystem::temp_directory_path() / "curvsph_surge_front_test";
  std::filesystem::create_directories(dir);
  // Experiment: Z = 1 + T exactly at T = 1, 2; the simulated front will be Z = 1 + 1.1 T.
  std::ofstream(dir / "front.csv") << "T,Z\n1,2\n2,3\n50,51\n";
  YAML::Node root = YAML::Load(R"(
dimension: 2
resolution: {dx: 0.01}
fluids: [{rho0: 1000, region: {box: {min: [0, 0], max: [0.1, 0.2]}}}]
eos: {c0: 10}
gravity: [0, -9.81]
time: {end: 1}
analysis: {surge_front: {wall: 0, width: 0.1, far_wall: 5, experiment: front.csv}}
)");
  const Case c = read_case(root, dir / "case.yaml");
  auto a = make_analysis<2>("surge_front", c.root["analysis"]["surge_front"], c);
  const double a_w = 0.1, g = 9.81, scale = std::sqrt(2 * g / a_w), dx = 0.01;
  for (int k = 0; k <= 30; ++k) {
    const double T = 0.1 * k, t = T / scale;
    // A sheet of water three rows thick whose edge is at x = a (1 + 1.1 T) (its last column dx/2
    // inside), a particle sliding on the floor ahead of it at a (1 + 1.2 T) + dx and a droplet in
    // the air further ahead.
    const double edge = a_w * (1 + 1.1 * T);
    Particles<2> P;
    const auto add = [&](double x, double y) {
      P.resize(P.size() + 1);
      P.x.back() = Vec<2>(static_cast<Real>(x), static_cast<Real>(y));
      P.rho.back() = 1000;
      P.mass.back() = static_cast<Real>(1000 * dx * dx);
    };
    for (double x = edge - dx / 2; x > 0; x -= dx)
      for (int j = 0; j < 3; ++j) add(x, (j + 0.5) * dx);
    const double spray = a_w * (1 + 1.2 * T) + dx;
    add(spray, dx / 2);
    add(spray + 0.3, 0.1);
    a->observe(t, P);
  }
  nlohmann::json m;
  a->finish(3.0 / scale, Particles<2>(), m, dir);
  EXPECT_EQ(m["surge_front_points"].get<long>(), 2);  // T = 50 lies beyond the run
  // The wet front against the experiment: |1 + 1.1 T - (1 + T)| / (1 + T): 0.05 at T = 1, 0.0667
  // at T = 2 (within the front's resolution, a few thousandths of dx).
  EXPECT_NEAR(m["surge_front_max_rel_error"].get<double>(), 0.2 / 3, 1e-3);
  EXPECT_NEAR(m["surge_front_rms_rel_error"].get<double>(),
              std::sqrt((0.05 * 0.05 + (0.2 / 3) * (0.2 / 3)) / 2), 1e-3);
  // The largest x on the floor is the sliding particle: (1 + 1.2 T + dx/a - (1 + T)) / (1 + T).
  const double e1 = (0.2 + 0.1) / 2, e2 = (0.4 + 0.1) / 3;
  EXPECT_NEAR(m["surge_front_largest_x_max_rel_error"].get<double>(), e2, 1e-5);
  EXPECT_NEAR(m["surge_front_largest_x_rms_rel_error"].get<double>(),
              std::sqrt((e1 * e1 + e2 * e2) / 2), 1e-5);
  // The wet front reaches Z = 2 at T = 1/1.1 and Z = 3 at T = 2/1.1: lags 1 - 1/1.1, 2 - 2/1.1;
  // speeds over Z >= 3/2 (both points): 1.1 simulated, 1 measured.
  EXPECT_NEAR(m["surge_front_lag_first"].get<double>(), 1 - 1 / 1.1, 2e-3);
  EXPECT_NEAR(m["surge_front_lag_last"].get<double>(), 2 - 2 / 1.1, 2e-3);
  EXPECT_NEAR(m["surge_front_speed"].get<double>(), 1.1, 2e-3);
  EXPECT_NEAR(m["surge_front_speed_experiment"].get<double>(), 1.0, 1e-9);
  EXPECT_TRUE(std::isnan(m["surge_front_t_far_wall"].get<double>()));
  EXPECT_TRUE(std::filesystem::exists(dir / "surge_front.csv"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curvsph
