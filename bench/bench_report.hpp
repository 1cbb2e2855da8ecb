#pragma once
// The counters every phase benchmark reports: `particles` processed per call and
// `particles_per_second` over the wall clock (the loops are OpenMP-parallel: UseRealTime).
#include <benchmark/benchmark.h>

#include <cstddef>

namespace curvsph {

inline void report_particles(benchmark::State& state, std::size_t n) {
  state.counters["particles"] = static_cast<double>(n);
  state.counters["particles_per_second"] =
      benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

}  // namespace curvsph
