// The surge-front analysis (analysis/surge_front.hpp) on synthetic particle sets whose front
// moves by a known law: the reduced front Z(T) it records and its relative error against a
// CSV "experiment" written for the test, computed by hand here.
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
  const double a_w = 0.1, g = 9.81, scale = std::sqrt(2 * g / a_w);
  for (int k = 0; k <= 30; ++k) {
    const double T = 0.1 * k, t = T / scale;
    Particles<2> P;
    P.resize(3);
    P.x[0] = Vec<2>(0.005, 0.005);
    P.x[1] = Vec<2>(static_cast<Real>(a_w * (1 + 1.1 * T)), 0.006);  // the front, on the floor
    P.x[2] = Vec<2>(static_cast<Real>(a_w * (3 + 1.1 * T)), 0.1);    // a droplet ahead, in the air
    a->observe(t, P);
  }
  nlohmann::json m;
  a->finish(3.0 / scale, Particles<2>(), m, dir);
  EXPECT_EQ(m["surge_front_points"].get<long>(), 2);  // T = 50 lies beyond the run
  // |1 + 1.1 T - (1 + T)| / (1 + T): 0.05 at T = 1, 0.0667 at T = 2.
  EXPECT_NEAR(m["surge_front_max_rel_error"].get<double>(), 0.2 / 3, 1e-5);
  EXPECT_NEAR(m["surge_front_rms_rel_error"].get<double>(),
              std::sqrt((0.05 * 0.05 + (0.2 / 3) * (0.2 / 3)) / 2), 1e-5);
  EXPECT_TRUE(std::isnan(m["surge_front_t_far_wall"].get<double>()));
  EXPECT_TRUE(std::filesystem::exists(dir / "surge_front.csv"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curvsph
