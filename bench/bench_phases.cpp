// One benchmark per phase of a step (issue 7), each on the state of a 3-D periodic box
// (cases/periodic_box_3d.yaml's set-up: h/dx = 1.3, 30^3 = 27 000 particles) after one
// solver step, so the fields are those of a running simulation:
//   neighbours (cell-list build), density summation, renormalised density gradient,
//   continuity rate with delta-SPH, fluid forces, kick-drift integration, re-sort (permute),
//   output (one VTK snapshot of every field, as `curvsph run` writes it, to the temporary
//   directory: the disk's speed is part of it).
// Counter particles_per_second = particles processed per wall-clock second (UseRealTime: the
// loops are OpenMP-parallel). Ratios between phases are what to read; absolute rates depend
// on the machine and its load.
//   build/curvsph_bench --benchmark_filter=Phase --benchmark_min_time=0.2
#include <benchmark/benchmark.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <memory>

#include "bench_report.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/io/vtk_writer.hpp"
#include "curvsph/physics/density.hpp"
#include "curvsph/physics/momentum.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {
namespace {

// The shared state: built once, the phases run on copies of its fields.
struct BoxState {
  std::unique_ptr<Solver<3>> solver;
  BoxState() {
    const char* yaml = R"(
name: bench_phases
dimension: 3
resolution: {dx: 0.0333333333333333, h_over_dx: 1.3}
domain: {min: [0, 0, 0], max: [1, 1, 1], periodic: [true, true, true]}
fluids:
  - {name: fluid, rho0: 1000, viscosity: 1.0e-3, region: {box: {min: [0, 0, 0], max: [1, 1, 1]}},
     velocity: [0.1, 0.05, 0.0]}
eos: {type: tait, c0: 10, p0: 1000}
density: {method: continuity, delta_sph: 0.1}
time: {end: 1.0, cfl: 0.2}
)";
    solver = std::make_unique<Solver<3>>(read_case(YAML::Load(yaml), "bench_phases"));
    solver->initialize();
    solver->step();
  }
};

BoxState& box() {
  static BoxState s;
  return s;
}

void BM_PhaseNeighbors(benchmark::State& state) {
  auto& s = *box().solver;
  CellList<3> cells = s.cells();
  for (auto _ : state) {
    cells.build(s.particles().x);
    benchmark::DoNotOptimize(cells.sorted().data());
  }
  report_particles(state, s.particles().size());
}

void BM_PhaseDensitySummation(benchmark::State& state) {
  auto& s = *box().solver;
  Particles<3> P = s.particles();
  for (auto _ : state) {
    density_summation(P, s.cells(), s.kernel());
    benchmark::DoNotOptimize(P.rho.data());
  }
  report_particles(state, P.size());
}

void BM_PhaseDensityGradient(benchmark::State& state) {
  auto& s = *box().solver;
  const Particles<3>& P = s.particles();
  std::vector<Vec<3>> grad;
  PairFactors<3> pf;
  for (auto _ : state) {
    renormalised_density_gradient(P, s.cells(), s.kernel(), grad, pf);
    benchmark::DoNotOptimize(grad.data());
  }
  report_particles(state, P.size());
}

void BM_PhaseContinuityRate(benchmark::State& state) {
  auto& s = *box().solver;
  Particles<3> P = s.particles();
  std::vector<Vec<3>> grad;
  PairFactors<3> pf;
  renormalised_density_gradient(P, s.cells(), s.kernel(), grad, pf);
  const Real dhc = s.fluid().delta_sph * s.kernel().h * s.fluid().eos.c0;
  for (auto _ : state) {
    continuity_rate(P, s.cells(), s.kernel(), dhc, &grad, pf);
    benchmark::DoNotOptimize(P.drho.data());
  }
  report_particles(state, P.size());
}

void BM_PhaseFluidForces(benchmark::State& state) {
  auto& s = *box().solver;
  Particles<3> P = s.particles();
  PairFactors<3> pf;
  for (auto _ : state) {
    fluid_forces(P, s.cells(), s.kernel(), s.fluid(), pf);
    benchmark::DoNotOptimize(P.a.data());
  }
  report_particles(state, P.size());
}

void BM_PhaseIntegrate(benchmark::State& state) {
  auto& s = *box().solver;
  Particles<3> P = s.particles();
  const Real dt = 1e-9;  // positions barely move: every iteration sees the same state
  for (auto _ : state) {
    parallel_for(static_cast<Index>(P.size()), [&](Index i) {
      P.v[i] += dt * P.a[i];
      P.x[i] += dt * P.v[i];
      s.cells().wrap(P.x[i]);
    });
    benchmark::DoNotOptimize(P.x.data());
  }
  report_particles(state, P.size());
}

void BM_PhaseResort(benchmark::State& state) {
  auto& s = *box().solver;
  Particles<3> P = s.particles();
  const auto& sorted = s.cells().sorted();
  const std::vector<std::size_t> order(sorted.begin(), sorted.end());
  for (auto _ : state) {
    P.permute(order);
    benchmark::DoNotOptimize(P.x.data());
  }
  report_particles(state, P.size());
}

void BM_PhaseOutput(benchmark::State& state) {
  const auto& P = box().solver->particles();
  const auto file = std::filesystem::temp_directory_path() / "curvsph_bench_phase_output.vtp";
  for (auto _ : state) io::write_vtp(file, P);
  std::filesystem::remove(file);
  report_particles(state, P.size());
}

BENCHMARK(BM_PhaseNeighbors)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PhaseDensitySummation)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PhaseDensityGradient)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PhaseContinuityRate)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PhaseFluidForces)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PhaseIntegrate)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PhaseResort)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PhaseOutput)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace curvsph
