#pragma once
// Progress of a long run: on a terminal one line updated in place (step, t / t_end, dt,
// ETA, particle-steps/s), as wide as the terminal allows (TIOCGWINSZ); in a pipe or file a
// new line every few seconds, at most 79 characters. The dt shown is the step the stability
// limits give (Solver::stable_step()), not the step cut short to land on an output time.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace curvsph {

// The figures of one progress line.
struct ProgressFigures {
  long step = 0;
  double t = 0, t_end = 0, dt = 0;
  double rate = 0;  // particle-steps per second
  double eta = -1;  // seconds; < 0: unknown
};

// The line for `f` in at most `width` characters: the parts that do not fit are dropped from
// the least useful (the rate, then the ETA, then dt) and what still does not fit is cut.
std::string progress_line(const ProgressFigures& f, std::size_t width);

// Columns of the terminal on stderr (TIOCGWINSZ), or 0 when stderr is not a terminal.
std::size_t terminal_columns();

class Progress {
 public:
  Progress(bool enabled, double t_end, std::size_t particles);
  void update(long step, double t, double dt, bool force = false);
  void finish();

 private:
  bool enabled_, tty_;
  double t_end_;
  std::size_t particles_;
  std::chrono::steady_clock::time_point start_, last_;
  bool printed_ = false;
};

}  // namespace curvsph
