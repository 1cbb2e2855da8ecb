#pragma once
// Progress of a long run: on a terminal one line updated in place (step, t / t_end, dt,
// particle-steps/s, ETA); in a pipe or file a new line every few seconds.
#include <chrono>
#include <cstdio>
#include <string>

namespace curvsph {

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
