#include "curvsph/solver/progress.hpp"

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <vector>

#include "curvsph/core/stage_report.hpp"

namespace curvsph {

namespace {

// 75 s, 12m05s, 3h02m: short and unambiguous.
std::string duration(double s) {
  if (s < 100) return fmt::format("{:.0f} s", s);
  const long m = static_cast<long>(s / 60 + 0.5);
  if (m < 100) return fmt::format("{}m{:02d}s", m, static_cast<int>(s) % 60);
  return fmt::format("{}h{:02d}m", m / 60, m % 60);
}

}  // namespace

std::string progress_line(const ProgressFigures& f, std::size_t width) {
  const double frac = f.t_end > 0 ? f.t / f.t_end : 1;
  // In order of use; the later ones go first when the line is too long.
  std::vector<std::string> parts{
      fmt::format("step {}", f.step),
      fmt::format("t {:.5g}/{:.5g} ({:.1f}%)", f.t, f.t_end, 100 * frac),
      fmt::format("dt {:.3g}", f.dt),
  };
  if (f.eta >= 0) parts.push_back("ETA " + duration(f.eta));
  parts.push_back(fmt::format("{:.3g} particle-steps/s", f.rate));
  std::string line;
  while (!parts.empty()) {
    line.clear();
    for (const auto& p : parts) line += (line.empty() ? "" : "  ") + p;
    if (line.size() <= width) return line;
    parts.pop_back();
  }
  return line.substr(0, width);
}

std::size_t terminal_columns() {
  if (!isatty(fileno(stderr))) return 0;
  winsize w{};
  if (ioctl(fileno(stderr), TIOCGWINSZ, &w) != 0 || w.ws_col == 0) return 80;
  return w.ws_col;
}

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
  ProgressFigures f;
  f.step = step;
  f.t = t;
  f.t_end = t_end_;
  f.dt = dt;
  f.rate = elapsed > 0 ? static_cast<double>(step) * particles_ / elapsed : 0;
  const double frac = t_end_ > 0 ? t / t_end_ : 1;
  f.eta = frac > 0 ? elapsed * (1 - frac) / frac : -1;
  // On a terminal, one column short of its width: a line that fills the last column wraps
  // on some terminals and the \r then rewrites only its second half.
  const std::size_t cols = tty_ ? terminal_columns() : 0;
  const std::string line = progress_line(f, tty_ ? (cols > 1 ? cols - 1 : 79) : 79);
  print_status_line(line, tty_);
  printed_ = true;
}

void Progress::finish() {
  if (enabled_ && tty_ && printed_) fmt::print(stderr, "\n");
}

}  // namespace curvsph
