#include "curvsph/core/stage_report.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>

namespace curvsph {

void print_status_line(const std::string& line, bool tty) {
  if (tty)
    fmt::print(stderr, "\r{}\033[K", line);
  else
    fmt::print(stderr, "{}\n", line);
  std::fflush(stderr);
}

namespace {
std::atomic<bool> g_enabled{false};
constexpr std::size_t kWidth = 79;
}  // namespace

void set_stage_reports(bool enabled) {
  g_enabled = enabled;
}
bool stage_reports() {
  return g_enabled;
}

StageReport::StageReport(std::string stage)
    : enabled_(g_enabled),
      tty_(isatty(fileno(stderr)) != 0),
      stage_(std::move(stage)),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void StageReport::print(const std::string& detail) {
  const double s = std::chrono::duration<double>(last_ - start_).count();
  const std::string line =
      fmt::format("setup: {}, {:.0f} s{}{}", stage_, s, detail.empty() ? "" : ": ", detail)
          .substr(0, kWidth);
  print_status_line(line, tty_);
  printed_ = true;
}

StageReport::~StageReport() {
  if (!enabled_) return;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (!printed_ && s < kStageReportAfter) return;
  const std::string line =
      fmt::format("setup: {} done in {:.1f} s{}{}", stage_, s, result_.empty() ? "" : ": ", result_)
          .substr(0, kWidth);
  // On a terminal it replaces the line updated in place.
  const bool over = tty_ && printed_;
  fmt::print(stderr, "{}{}{}\n", over ? "\r" : "", line, over ? "\033[K" : "");
  std::fflush(stderr);
}

}  // namespace curvsph
