#pragma once
// Loops over index ranges, threaded with OpenMP. Static scheduling keeps every particle on
// the same thread for a given thread count, and each iteration writes only its own index,
// so results are deterministic (DESIGN.md: deterministic for a given thread count).
#include <omp.h>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <class F>
void parallel_for(Index n, F&& f) {
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) f(i);
}

// parallel_for() for loops whose work sits in a few stretches of [0, n) (the particles near
// walls, in cell order; the boundary elements with fluid around them): chunks are handed out
// as threads free up, where a static split would give one thread most of the work. f(i)
// must write only index i's results, so results do not depend on the schedule.
template <class F>
void parallel_for_balanced(Index n, F&& f, int chunk = 256) {
#pragma omp parallel for schedule(dynamic, chunk)
  for (Index i = 0; i < n; ++i) f(i);
}

// Max-reduction of f(i) over [0, n).
template <class F>
Real parallel_max(Index n, Real init, F&& f) {
  Real m = init;
#pragma omp parallel for schedule(static) reduction(max : m)
  for (Index i = 0; i < n; ++i) {
    const Real v = f(i);
    if (v > m) m = v;
  }
  return m;
}

inline int thread_count() {
  return omp_get_max_threads();
}

}  // namespace curvsph
