// Vela Vela et al. Table 1: cost of placing density-preserving ghosts relative to mirror
// ghosts (10^6 random interior particles; cylinder, sphere, torus a = 1, R = 3; 2h = 0.1).
// Counters: ghost_cost_increase_pct_<shape>, from ghost_cost_study() (both maps timed in
// the same run, interleaved, best of the repeats).
#include <benchmark/benchmark.h>

#include "curvsph/analysis/ghost_cost.hpp"

static void BM_GhostCostVelaVelaTable1(benchmark::State& state) {
  curvsph::GhostCostOptions opt;
  opt.particles = static_cast<std::size_t>(state.range(0));
  opt.repeats = static_cast<int>(state.range(1));
  curvsph::GhostCostResult res;
  for (auto _ : state) {
    res = curvsph::ghost_cost_study(opt);
    benchmark::DoNotOptimize(res.cylinder_pct);
  }
  for (const auto& s : res.shapes) {
    state.counters["ghost_cost_increase_pct_" + s.shape] = s.increase_pct;
    state.counters["ghost_mirror_ms_" + s.shape] = 1e3 * s.mirror_s;
    state.counters["ghost_density_preserving_ms_" + s.shape] = 1e3 * s.density_preserving_s;
  }
}
BENCHMARK(BM_GhostCostVelaVelaTable1)
    ->Args({1000000, 7})
    ->Args({1000000, 25})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
