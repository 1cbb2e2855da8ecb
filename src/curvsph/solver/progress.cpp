#include "curvsph/solver/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

namespace curvsph {

Progress::Progress(bool enabled, double t_end, std::size_t particles)
    : enabled_(enabled),
      tty_(isatty(fileno(stderr)) != 0),
      t_end_(t_end),
      particles_(particles),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void Progress::update(long step, double t, double dt, bool force) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (!force && since < (tty_ ? 0.25 : 5.0)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(step) * particles_ / elapsed : 0;
  const double frac = t_end_ > 0 ? t / t_end_ : 1;
  const double eta = frac > 0 ? elapsed * (1 - frac) / frac : 0;
  const std::string line = fmt::format(
      "step {:>8}  t = {:.5g} / {:.5g} ({:5.1f}%)  dt = {:.3e}  {:.3e} particle-steps/s  "
      "ETA {:.0f} s",
      step, t, t_end_, 100 * frac, dt, rate, eta);
  if (tty_)
    fmt::print(stderr, "\r{}\033[K", line);
  else
    fmt::print(stderr, "{}\n", line);
  std::fflush(stderr);
  printed_ = true;
}

void Progress::finish() {
  if (enabled_ && tty_ && printed_) fmt::print(stderr, "\n");
}

}  // namespace curvsph
