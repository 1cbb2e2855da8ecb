#pragma once
// SIGINT / SIGTERM during a run: the time loop ends after the current step (run.hpp), the run
// writes its outputs as if time.end had been reached there, then returns (`curvsph run`) or
// throws Interrupted (`curvsph validate`, after stop_ends_program(true)): a study running many
// cases stops after the current run instead of starting the next one, where the stop used to
// be swallowed by the next run resetting it (`validate all` ran on through Ctrl-C).

namespace curvsph {

// A run stopped by SIGINT or SIGTERM where the stop ends the program: the exit code is
// 128 + signal, the shells' convention (130 for SIGINT). Not a std::exception, so that the
// handlers of failed runs in the studies (catch std::exception) let it through.
struct Interrupted {
  int signal;
};

// Installs the stop handler for SIGINT and SIGTERM while at least one StopOnSignal lives
// (runs of a study may overlap on threads) and puts the previous handlers back when the last
// one goes. Outside runs the default handlers apply: the signal ends the process at once.
class StopOnSignal {
 public:
  StopOnSignal();
  ~StopOnSignal();
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;
};

// The signal that asked the running time loops to stop (SIGINT or SIGTERM), 0 when none.
int stop_signal();

// true: a stop is kept for the rest of the program (a new run does not clear it, and starts
// by throwing Interrupted) and a stopped run throws Interrupted after writing its outputs.
// false (default): each run starts afresh and a stopped run returns its metrics.
void stop_ends_program(bool on);
bool stop_ends_program();

}  // namespace curvsph
