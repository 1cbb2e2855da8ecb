// Closest-point throughput on NURBS walls with boundary-particle seeds (Barker §3.2): the seed
// is the parameter of the nearest arc-length sample at spacing dx (surfaces: the nearest
// near-uniform sample), tolerance 0.01 dx. Counters: queries per second, mean and max Newton
// iterations (derivative evaluations of the seeded path), share of queries where the global
// certificate changed the answer. "Unseeded" runs the global search alone for comparison.
#include <benchmark/benchmark.h>

#include <random>

#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/geometry/nurbs_surface_wall.hpp"

using namespace curvsph;

namespace {

nurbs::NurbsCurve<2> wavy_curve() {
  // Degree 3, 24 control points along a wave, non-uniform knots, weights in [0.5, 2].
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> W(0.5, 2.0), J(-0.1, 0.1);
  const int n = 24, p = 3;
  std::vector<Vec2d> P;
  std::vector<double> w, k(p + 1, 0.0);
  for (int i = 0; i < n; ++i) {
    P.emplace_back(0.05 * i, 0.05 * std::sin(0.8 * i) + 0.01 * J(rng));
    w.push_back(W(rng));
  }
  for (int i = 1; i < n - p; ++i) k.push_back(i + 0.3 * J(rng) / 0.1 * 0.5);
  for (int i = 0; i <= p; ++i) k.push_back(n - p);
  return nurbs::NurbsCurve<2>(p, P, w, k);
}

nurbs::NurbsSurface wavy_surface() {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> W(0.5, 2.0);
  const int n = 10, p = 3;
  std::vector<std::vector<Vec3d>> P(n, std::vector<Vec3d>(n));
  std::vector<std::vector<double>> w(n, std::vector<double>(n));
  std::vector<double> k(p + 1, 0.0);
  for (int i = 1; i < n - p; ++i) k.push_back(i);
  for (int i = 0; i <= p; ++i) k.push_back(n - p);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      P[i][j] = Vec3d(0.05 * i, 0.05 * j, 0.04 * std::sin(0.9 * i) * std::cos(0.7 * j));
      w[i][j] = W(rng);
    }
  return nurbs::NurbsSurface(p, p, P, w, k, k);
}

template <int D>
struct Queries {
  std::vector<VecD<D>> x;
  std::vector<ParamSeed> seed;
};

// Points within 2h = 2.6 dx of the wall on both sides, seeded by the nearest sample.
template <int D, class Wall, class Samples>
Queries<D> make_queries(const Wall& wall, const Samples& s, double dx, int count) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::uniform_int_distribution<std::size_t> pick(0, s.points.size() - 1);
  Queries<D> q;
  for (int k = 0; k < count; ++k) {
    const std::size_t i = pick(rng);
    const WallPoint<D> on = wall.closest(s.points[i]);
    VecD<D> x = s.points[i] + 2.6 * dx * U(rng) * on.normal;
    for (int d = 0; d < D; ++d) x[d] += 0.5 * dx * U(rng);
    std::size_t best = 0;
    for (std::size_t j = 0; j < s.points.size(); ++j)
      if ((s.points[j] - x).squaredNorm() < (s.points[best] - x).squaredNorm()) best = j;
    ParamSeed seed;
    if constexpr (D == 2) {
      seed.param = {s.params[best], 0.0};
    } else {
      seed.param = s.params[best];
    }
    seed.valid = true;
    q.x.push_back(x);
    q.seed.push_back(seed);
  }
  return q;
}

template <int D, class Wall>
void run(benchmark::State& state, const Wall& wall, const Queries<D>& q, bool seeded) {
  long total_it = 0, queries = 0;
  int max_it = 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const WallPoint<D> p = wall.closest(q.x[i], seeded ? q.seed[i] : ParamSeed{});
    benchmark::DoNotOptimize(p);
    total_it += p.iterations;
    max_it = std::max(max_it, p.iterations);
    ++queries;
    i = (i + 1) % q.x.size();
  }
  state.counters["queries_per_s"] = benchmark::Counter(queries, benchmark::Counter::kIsRate);
  state.counters["newton_mean"] = queries ? double(total_it) / queries : 0.0;
  state.counters["newton_max"] = max_it;
}

const double kDxCurve = 0.005, kDxSurface = 0.01;

const NurbsCurveWall& curve_wall() {
  static const NurbsCurveWall w(wavy_curve(), NurbsCurveWall::Side::left, 0.01 * kDxCurve);
  return w;
}
const Queries<2>& curve_queries() {
  static const Queries<2> q =
      make_queries<2>(curve_wall(), curve_wall().boundary_particles(kDxCurve), kDxCurve, 4096);
  return q;
}
const NurbsSurfaceWall& surface_wall() {
  static const NurbsSurfaceWall w(wavy_surface(), NurbsSurfaceWall::Side::front, 0.01 * kDxSurface);
  return w;
}
const Queries<3>& surface_queries() {
  static const Queries<3> q =
      make_queries<3>(surface_wall(), surface_wall().seeds(kDxSurface), kDxSurface, 4096);
  return q;
}

void BM_NurbsCurveClosestSeeded(benchmark::State& s) {
  run<2>(s, curve_wall(), curve_queries(), true);
}
void BM_NurbsCurveClosestUnseeded(benchmark::State& s) {
  run<2>(s, curve_wall(), curve_queries(), false);
}
void BM_NurbsSurfaceClosestSeeded(benchmark::State& s) {
  run<3>(s, surface_wall(), surface_queries(), true);
}
void BM_NurbsSurfaceClosestUnseeded(benchmark::State& s) {
  run<3>(s, surface_wall(), surface_queries(), false);
}

}  // namespace

BENCHMARK(BM_NurbsCurveClosestSeeded);
BENCHMARK(BM_NurbsCurveClosestUnseeded);
BENCHMARK(BM_NurbsSurfaceClosestSeeded);
BENCHMARK(BM_NurbsSurfaceClosestUnseeded);
