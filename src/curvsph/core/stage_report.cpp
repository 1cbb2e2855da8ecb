#include "curvsph/core/stage_report.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cstdio>

namespace curvsph {

namespace {
std::atomic<bool> g_enabled{false};
}

void set_stage_reports(bool enabled) {
  g_enabled = enabled;
}
bool stage_reports() {
  return g_enabled;
}

StageReport::StageReport(std::string stage)
    : enabled_(g_enabled),
      stage_(std::move(stage)),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void StageReport::print(const std::string& detail) {
  const double s = std::chrono::duration<double>(last_ - start_).count();
  fmt::print(stderr, "setup: {} ({:.0f} s){}{}\n", stage_, s, detail.empty() ? "" : ": ", detail);
  std::fflush(stderr);
  printed_ = true;
}

StageReport::~StageReport() {
  if (!enabled_) return;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (!printed_ && s < kStageReportAfter) return;
  fmt::print(stderr, "setup: {} done in {:.1f} s{}{}\n", stage_, s, result_.empty() ? "" : ": ",
             result_);
  std::fflush(stderr);
}

}  // namespace curvsph
