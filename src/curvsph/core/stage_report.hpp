#pragma once
// Set-up stages that can take seconds (the particle fill, the packing of setup/relax, the
// wall elements of boundary integrals) say so on stderr once they run longer than
// kStageReportAfter, so that a long set-up does not look like a hang: while the stage runs,
// a line updated in place on a terminal (a new line every kStagePipeEvery in a pipe), when
// it has figures to show, and a closing line. Quick stages print nothing. Lines are cut at
// 79 characters. Off unless the run enables it (`curvsph run` without --quiet, on MPI rank
// 0): library users and tests stay silent.
#include <chrono>
#include <string>

namespace curvsph {

// Writes a status line to stderr: rewritten in place on a terminal (tty), a line of its own in
// a pipe; flushed. Shared by the set-up stage lines and the time loop's progress line.
void print_status_line(const std::string& line, bool tty);

inline constexpr double kStageReportAfter = 2.0;  // seconds
inline constexpr double kStagePipeEvery = 5.0;    // seconds, as the progress line in a pipe

void set_stage_reports(bool enabled);
bool stage_reports();

class StageReport {
 public:
  explicit StageReport(std::string stage);
  ~StageReport();
  StageReport(const StageReport&) = delete;
  StageReport& operator=(const StageReport&) = delete;

  // `detail()` (a std::string) is called, and its line printed, only when one is due: after
  // kStageReportAfter, then every 0.25 s on a terminal, every kStagePipeEvery in a pipe.
  template <class F>
  void tick(F&& detail) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    const double wait = !printed_ ? kStageReportAfter : tty_ ? 0.25 : kStagePipeEvery;
    if (std::chrono::duration<double>(now - (printed_ ? last_ : start_)).count() < wait) return;
    last_ = now;
    print(detail());
  }
  // The closing line's figures ("12345 particles"); shown when the stage took long.
  void result(std::string text) { result_ = std::move(text); }

 private:
  void print(const std::string& detail);
  bool enabled_, tty_;
  std::string stage_, result_;
  std::chrono::steady_clock::time_point start_, last_;
  bool printed_ = false;
};

}  // namespace curvsph
