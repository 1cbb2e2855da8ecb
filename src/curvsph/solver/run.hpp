#pragma once
// A whole run of a case: the time loop around Solver with outputs (VTK series, probes,
// log.txt), the case's analyses and metrics.json (DESIGN.md §3).
#include <filesystem>
#include <nlohmann/json.hpp>

#include "curvsph/io/case_file.hpp"

namespace curvsph {

struct RunOptions {
  std::filesystem::path out_dir = "out";
  int threads = 0;          // 0: OpenMP default
  bool progress = true;     // progress line and set-up stage lines on stderr (rank 0)
  bool warnings = true;     // warnings on stderr (rank 0), whatever `progress` says
  bool write_files = true;  // false: no VTK/probes/log (validation sweeps); metrics still returned
  // A snapshot (.vtp) of an earlier run of the same case to start from instead of the case's
  // initial particles; its time is read from the series.pvd beside it. Empty: start at t = 0.
  std::filesystem::path restart;
  // Runs whose schedule asks for more than kMaxSnapshots snapshots or kMaxProbeRows probe rows
  // are refused up front (exit 2) unless `force` (`run --force`).
  bool force = false;
  // Refuse up front (exit 2) a run whose estimated memory exceeds this many bytes
  // (solver/run_guards.hpp); 0: 80 % of the physical memory. `run --max-memory`.
  double max_memory = 0;
  // out_dir holding another run's files (series.pvd, particles_*.vtp, metrics.json, ...):
  // refused (exit 2) unless `overwrite`, which removes those files first. `run --overwrite`.
  bool overwrite = false;
};

// Runs the case; returns the metrics (also written to out_dir/metrics.json). On instability it
// writes a last snapshot and rethrows InstabilityError (a time step that collapses, below
// 1e-12 time.end or too small to advance t, is one). SIGINT or SIGTERM during the time loop
// ends the run after the current step as if time.end had been reached there (the analyses
// run, metrics.json is written with `stopped` = 1 and the time reached), so that a long run
// cut short by hand still leaves its figures; then, where stop_ends_program() is set
// (solver/stop_signal.hpp), it throws Interrupted instead of returning.
nlohmann::json run_case(const Case& c, const RunOptions& options);

}  // namespace curvsph
