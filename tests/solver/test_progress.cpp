// The progress line (solver/progress.hpp) fits the width it is given, dropping its least
// useful parts first, and set-up stages (core/stage_report.hpp) speak only when they take
// longer than kStageReportAfter.
#include <gtest/gtest.h>

#include <thread>

#include "curvsph/core/stage_report.hpp"
#include "curvsph/solver/progress.hpp"

namespace curvsph {
namespace {

TEST(ProgressLine, FitsTheWidthDroppingTheRateFirst) {
  ProgressFigures f;
  f.step = 123456789;
  f.t = 1.23456789e-5;
  f.t_end = 6.0e+1;
  f.dt = 1.2345e-12;
  f.rate = 1.2345e+7;
  f.eta = 3.7e5;
  const std::string wide = progress_line(f, 200);
  // Everything at 200 columns, in order.
  EXPECT_NE(wide.find("step 123456789"), std::string::npos) << wide;
  EXPECT_NE(wide.find("dt 1.23e-12"), std::string::npos) << wide;
  EXPECT_NE(wide.find("ETA 102h47m"), std::string::npos) << wide;
  EXPECT_NE(wide.find("particle-steps/s"), std::string::npos) << wide;
  for (std::size_t width : {79u, 60u, 40u, 10u}) {
    const std::string line = progress_line(f, width);
    EXPECT_LE(line.size(), width) << line;
    EXPECT_EQ(line.rfind("step ", 0), 0u) << line;
  }
  // At 79 the rate goes before the ETA; at 60 both go, dt stays.
  EXPECT_EQ(progress_line(f, 79).find("particle-steps"), std::string::npos);
  EXPECT_NE(progress_line(f, 79).find("ETA"), std::string::npos);
  EXPECT_NE(progress_line(f, 60).find("dt 1.23e-12"), std::string::npos);
  EXPECT_EQ(progress_line(f, 60).find("ETA"), std::string::npos);
  // A short run's line keeps everything in 79 columns.
  ProgressFigures g{120, 0.5, 1.0, 2.5e-3, 4.0e6, 12};
  EXPECT_EQ(progress_line(g, 79),
            "step 120  t 0.5/1 (50.0%)  dt 0.0025  ETA 12 s  4e+06 particle-steps/s");
}

TEST(StageReport, SilentWhenQuickOrDisabledReportsWhenSlow) {
  set_stage_reports(true);
  ::testing::internal::CaptureStderr();
  {
    StageReport quick("quick stage");
    quick.tick([] { return std::string("never"); });
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");

  ::testing::internal::CaptureStderr();
  {
    StageReport slow("slow stage");
    std::this_thread::sleep_for(
        std::chrono::milliseconds(static_cast<int>(1000 * kStageReportAfter) + 100));
    slow.tick([] { return std::string("step 3 / 10"); });
    slow.tick([] { return std::string("not yet due"); });
    slow.result("10 steps");
  }
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("setup: slow stage, 2 s: step 3 / 10\n"), std::string::npos) << err;
  EXPECT_EQ(err.find("not yet due"), std::string::npos) << err;
  EXPECT_NE(err.find("setup: slow stage done in 2."), std::string::npos) << err;
  EXPECT_NE(err.find(": 10 steps\n"), std::string::npos) << err;

  set_stage_reports(false);
  ::testing::internal::CaptureStderr();
  {
    StageReport off("off");
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

}  // namespace
}  // namespace curvsph
