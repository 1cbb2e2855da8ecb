#pragma once
// A whole run for a test: nothing written, no progress line, the metrics returned. Tests that
// run beside another multi-threaded test under `ctest -j 2` on 2 cores pass threads = 1 (an
// OpenMP barrier waiting for a descheduled thread turns seconds into minutes).
#include <nlohmann/json.hpp>

#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/run.hpp"

namespace curvsph::test {

inline nlohmann::json run_quiet(const Case& c, int threads = 0) {
  RunOptions o;
  o.write_files = false;
  o.progress = false;
  o.threads = threads;
  return run_case(c, o);
}

}  // namespace curvsph::test
