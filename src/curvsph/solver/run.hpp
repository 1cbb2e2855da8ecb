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
  bool progress = true;     // progress line on stderr
  bool write_files = true;  // false: no VTK/probes/log (validation sweeps); metrics still returned
};

// Runs the case; returns the metrics (also written to out_dir/metrics.json). On instability it
// writes a last snapshot and rethrows InstabilityError.
nlohmann::json run_case(const Case& c, const RunOptions& options);

}  // namespace curvsph
