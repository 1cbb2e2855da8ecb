#pragma once
// Set-up stages that can take seconds (the particle fill, the packing of setup/relax, the
// wall elements of boundary integrals) say so on stderr once they run longer than
// kStageReportAfter, so that a long set-up does not look like a hang: a line every few
// seconds while the stage runs (when it has figures to show) and one when it ends. Quick
// stages print nothing. Off unless the run enables it (`curvsph run` without --quiet, on
// MPI rank 0): library users and tests stay silent.
#include <chrono>
#include <string>

namespace curvsph {

inline constexpr double kStageReportAfter = 2.0;  // seconds

void set_stage_reports(bool enabled);
bool stage_reports();

class StageReport {
 public:
  explicit StageReport(std::string stage);
  ~StageReport();
  StageReport(const StageReport&) = delete;
  StageReport& operator=(const StageReport&) = delete;

  // `detail()` (a std::string) is called, and its line printed, only when one is due: after
  // kStageReportAfter, then at most every kStageReportAfter.
  template <class F>
  void tick(F&& detail) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_).count() < kStageReportAfter) return;
    last_ = now;
    print(detail());
  }
  // The closing line's figures ("12345 particles"); shown when the stage took long.
  void result(std::string text) { result_ = std::move(text); }

 private:
  void print(const std::string& detail);
  bool enabled_;
  std::string stage_, result_;
  std::chrono::steady_clock::time_point start_, last_;
  bool printed_ = false;
};

}  // namespace curvsph
