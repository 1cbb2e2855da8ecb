// Core benchmarks: cell-list build plus one neighbour sweep, and one full solver step on a
// periodic box. Each reports a throughput rate counter (particles or particle-steps per second)
// over wall-clock time (UseRealTime: the solver is OpenMP-parallel, and the main thread's CPU
// time would overstate the rate).
//   build/curvsph_bench --benchmark_min_time=0.01
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <random>
#include <vector>

#include "curvsph/io/case_file.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

// count[0] x count[1] (x count[2]) particles on a lattice of spacing dx, jittered by up to
// 0.2 dx per axis (fixed seed).
template <int D>
std::vector<Vec<D>> jittered_lattice(const std::array<int, 3>& count, double dx) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> U(-0.2, 0.2);
  long total = 1;
  for (int d = 0; d < D; ++d) total *= count[d];
  std::vector<Vec<D>> x(total);
  for (long k = 0; k < total; ++k) {
    long rest = k;
    for (int d = 0; d < D; ++d) {
      x[k][d] = (static_cast<double>(rest % count[d]) + 0.5 + U(rng)) * dx;
      rest /= count[d];
    }
  }
  return x;
}

// (a) Cell-list build + one sweep over all neighbour pairs (counting them), h/dx = 1.3.
template <int D>
void BM_CellListSweep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));  // particles per axis
  const double dx = 1.0 / n;
  const std::array<int, 3> count{n, n, D == 3 ? n : 1};
  auto x = jittered_lattice<D>(count, dx);
  CellList<D> cells;
  cells.configure(2 * 1.3 * dx, Vec3d::Zero(), Vec3d::Ones(), {true, true, true});
  for (auto& p : x) cells.wrap(p);
  long pairs = 0;
  for (auto _ : state) {
    cells.build(x);
    pairs = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      cells.for_each_neighbor(x[i], x, [&](Index, const Vec<D>&, Real) { ++pairs; });
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["particles"] = static_cast<double>(x.size());
  state.counters["pairs_per_particle"] = static_cast<double>(pairs) / static_cast<double>(x.size());
  state.counters["particles_per_second"] =
      benchmark::Counter(static_cast<double>(x.size()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK_TEMPLATE(BM_CellListSweep, 2)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();  // 10^4
BENCHMARK_TEMPLATE(BM_CellListSweep, 3)
    ->Arg(46)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();  // 97336

// (b) One full Solver<D>::step() (summation density, Tait EOS, viscosity) on a periodic box
// with a uniform lattice: range(0) particles along x and y, range(1) along z (3-D).
template <int D>
void BM_SolverStep(benchmark::State& state) {
  const int nx = static_cast<int>(state.range(0));
  const int nz = static_cast<int>(state.range(1));
  const double dx = 0.02;
  const double lx = nx * dx, lz = nz * dx;
  const std::string box =
      D == 3 ? fmt::format("[{}, {}, {}]", lx, lx, lz) : fmt::format("[{}, {}]", lx, lx);
  const std::string zero = D == 3 ? "[0, 0, 0]" : "[0, 0]";
  const std::string yaml = fmt::format(
      R"(
name: bench_periodic_box
dimension: {dim}
resolution: {{dx: {dx}, h_over_dx: 1.3}}
domain: {{min: {zero}, max: {box}, periodic: [{periodic}]}}
fluids:
  - {{name: water, rho0: 1000, viscosity: 1.0e-3, region: {{box: {{min: {zero}, max: {box}}}}},
     velocity: {velocity}}}
eos: {{type: tait, c0: 10, gamma: 7, p0: 100}}
density: {{method: summation}}
time: {{end: 1.0, cfl: 0.2}}
)",
      fmt::arg("dim", D), fmt::arg("dx", dx), fmt::arg("zero", zero), fmt::arg("box", box),
      fmt::arg("periodic", D == 3 ? "true, true, true" : "true, true"),
      fmt::arg("velocity", D == 3 ? "[0.1, 0, 0]" : "[0.1, 0]"));
  const Case c = read_case(YAML::Load(yaml), "bench");
  Solver<D> solver(c);
  solver.initialize();
  const double n = static_cast<double>(solver.particles().size());
  for (auto _ : state) solver.step();
  state.counters["particles"] = n;
  state.counters["particle_steps_per_second"] =
      benchmark::Counter(n * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK_TEMPLATE(BM_SolverStep, 2)
    ->Args({100, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();  // 10^4
BENCHMARK_TEMPLATE(BM_SolverStep, 3)
    ->Args({50, 40})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();  // 10^5

}  // namespace
}  // namespace curvsph
