#pragma once
// The thread count of a run, capped at the processors this process may run on.
#include <omp.h>

#include <algorithm>

namespace curvsph {

// A requested thread count capped at omp_get_num_procs() (the processors of the affinity
// mask, not the machine's total). More threads than that only oversubscribe the cores, and
// far more fail inside the OpenMP runtime: libgomp exited 1 when it could not create 512
// threads and crashed at 100000. `capped` says whether the request was lowered;
// requested <= 0 keeps the OpenMP default (threads = 0).
struct ThreadCount {
  int threads = 0;
  bool capped = false;
  int available = 1;
};

inline ThreadCount cap_threads(int requested) {
  const int available = std::max(1, omp_get_num_procs());
  if (requested <= 0) return {0, false, available};
  if (requested > available) return {available, true, available};
  return {requested, false, available};
}

}  // namespace curvsph
