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
