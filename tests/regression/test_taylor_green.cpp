// A short Taylor–Green run checked against the analytic solution (the full study is
// `curvsph validate taylor_green`; see docs/validation/taylor_green).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../support/quiet_run.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

TEST(RegressionTaylorGreen, ShortRunFollowsTheAnalyticDecay) {
  const Case c = read_case(std::string(CURVSPH_SOURCE_DIR) + "/cases/taylor_green_2d.yaml",
                           {"resolution.dx=0.02", "time.end=0.3", "output.vtk=false"});
  const auto m = test::run_quiet(c);
  EXPECT_EQ(m["particles"].get<long>(), 2500);
  // Kinetic energy against exp(-16 pi^2 nu t), nu = 0.01, computed here independently.
  const double ratio_exact = std::exp(-16 * std::numbers::pi * std::numbers::pi * 0.01 * 0.3);
  EXPECT_NEAR(m["kinetic_energy_ratio_reference"].get<double>(), ratio_exact, 1e-12);
  EXPECT_NEAR(m["kinetic_energy_ratio"].get<double>() / ratio_exact, 1.0, 0.08);
  EXPECT_LT(m["l2_velocity_error"].get<double>(), 0.06);
  EXPECT_NEAR(m["time_reached"].get<double>(), 0.3, 1e-12);
}

}  // namespace
}  // namespace curvsph
