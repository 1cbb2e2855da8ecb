// The boundary phases of a step (issue 7), each on the state of a running simulation of the
// case the throughput study times them on, at a resolution that builds in seconds:
//   BM_PhaseBoundaryIntegralsPrepass: BoundaryModel::prepare of the boundary integrals (element
//     pair search, element-averaged kernel, closest wall point, geometric Shepard factor) on
//     the 3-D dam break (cases/dam_break_3d.yaml at dx = 0.036, h/dx = 1.732: ~14 500 fluid
//     particles, ~11 000 elements);
//   BM_PhaseBoundaryIntegralsWallTerms: the wall terms of the same state (add_density_rate
//     and add_accelerations on the pairs of one prepare);
//   BM_PhaseBoundaryGhostPrepass: the ghost generation with the density-preserving map on the
//     Couette annulus (cases/couette.yaml as it is: ~12 000 particles, 2-D).
// Counter particles_per_second = fluid particles processed per wall-clock second (UseRealTime:
// the loops are OpenMP-parallel). Each benchmark owns its boundary model, built as the solver
// builds its own (make_boundary_model) and warmed by one prepare, so every iteration is a
// step's worth of work on fixed particles.
//   build/curvsph_bench --benchmark_filter=PhaseBoundary --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <memory>

#include "bench_report.hpp"
#include "curvsph/boundary/boundary_model.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/solver/solver.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

template <int D>
struct BoundaryState {
  std::unique_ptr<Solver<D>> solver;
  std::unique_ptr<BoundaryModel<D>> model;
  Particles<D> P;

  BoundaryState(const char* case_file, const std::vector<std::string>& overrides) {
    const Case c =
        read_case(std::filesystem::path(CURVSPH_SOURCE_DIR) / "cases" / case_file, overrides);
    solver = std::make_unique<Solver<D>>(c);
    solver->initialize();
    solver->step();
    const Solver<D>& s = *solver;
    model = make_boundary_model<D>(
        BoundaryContext<D>{s.spec(), s.walls(), s.kernel(), s.fluid(), s.cells()});
    P = s.particles();
    model->prepare(P, 0);  // builds the elements / checks the walls once
  }
};

const std::vector<std::string> kDamBreak = {"resolution.dx=0.036", "resolution.h_over_dx=1.732",
                                            "eos.c0=45", "time.cfl=0.2", "output.vtk=false"};

BoundaryState<3>& dam_break() {
  static BoundaryState<3> s("dam_break_3d.yaml", kDamBreak);
  return s;
}

BoundaryState<2>& couette() {
  static BoundaryState<2> s("couette.yaml",
                            {"boundary.map=density_preserving", "output.vtk=false"});
  return s;
}

// One pre-pass per iteration on the state's fixed particles.
template <int D>
void time_prepare(benchmark::State& state, BoundaryState<D>& s) {
  for (auto _ : state) {
    s.model->prepare(s.P, 0);
    benchmark::ClobberMemory();
  }
  report_particles(state, s.P.size());
}

void BM_PhaseBoundaryIntegralsPrepass(benchmark::State& state) {
  time_prepare(state, dam_break());
}

void BM_PhaseBoundaryIntegralsWallTerms(benchmark::State& state) {
  auto& s = dam_break();
  s.model->prepare(s.P, 0);
  Particles<3> P = s.P;
  for (auto _ : state) {
    // The wall terms scale what the fluid passes left in drho and a (by 1/gamma): start each
    // iteration from the same fields so that nothing grows or underflows.
    P.drho = s.P.drho;
    P.a = s.P.a;
    s.model->add_density_rate(P);
    s.model->add_accelerations(P);
    benchmark::DoNotOptimize(P.a.data());
  }
  report_particles(state, P.size());
}

void BM_PhaseBoundaryGhostPrepass(benchmark::State& state) {
  time_prepare(state, couette());
}

BENCHMARK(BM_PhaseBoundaryIntegralsPrepass)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PhaseBoundaryIntegralsWallTerms)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PhaseBoundaryGhostPrepass)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace curvsph
