#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "curvsph/analysis/shepard_approach.hpp"

using namespace curvsph;

TEST(ShepardApproach, GeometricBeatsFoilsAndWritesCsv) {
  ShepardApproachOptions o;
  o.samples = 21;
  const auto r = run_shepard_approach(o);
  ASSERT_EQ(r.curves.size(), 5u);
  for (const char* a :
       {"wall", "corner_side", "corner_diagonal", "circle_inside", "circle_outside"}) {
    EXPECT_LT(r.metrics.at(std::string("gamma_max_abs_error_") + a + "_geometric"), 1e-5) << a;
    EXPECT_GT(r.metrics.at(std::string("gamma_max_abs_error_") + a + "_monolithic"), 0.005) << a;
  }
  const auto dir = std::filesystem::temp_directory_path() /
                   ("curvsph_shepard_approach_" + std::to_string(::getpid()));
  write_shepard_approach(r, dir);
  std::ifstream csv(dir / "shepard_wall.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "distance_over_h,gamma_reference,gamma_geometric,gamma_monolithic,"
            "gamma_monolithic_contour,gamma_volume");
  std::ifstream js(dir / "metrics.json");
  const auto j = nlohmann::json::parse(js);
  EXPECT_TRUE(j.contains("gamma_max_abs_error_circle_geometric"));
  // The paper's contour rule puts gamma = 1/2 on a flat wall exactly (the plain foil: 1).
  const auto& wall = r.curves[0];
  EXPECT_NEAR(wall.gamma.at("monolithic_contour").back(), 0.5, 1e-12);
  EXPECT_NEAR(wall.gamma.at("monolithic").back(), 1.0, 1e-12);
  std::filesystem::remove_all(dir);
}
