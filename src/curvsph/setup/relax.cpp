#include "curvsph/setup/relax.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/stage_report.hpp"

namespace curvsph {

double relative_spread(const std::vector<Real>& v) {
  if (v.empty()) return 0;
  double s = 0, s2 = 0;
  for (Real x : v) {
    s += x;
    s2 += static_cast<double>(x) * x;
  }
  const double n = static_cast<double>(v.size());
  const double mean = s / n;
  const double var = std::max(0.0, s2 / n - mean * mean);
  return mean != 0 ? std::sqrt(var) / mean : 0.0;
}

template <int D>
void node_density(const std::vector<Vec<D>>& at, const std::vector<Vec<D>>& xf,
                  const CellList<D>& cf, const GhostSet<D>* G, const CellList<D>* cg,
                  const WendlandC2<D>& W, std::vector<Real>& n) {
  n.resize(at.size());
  parallel_for(static_cast<Index>(at.size()), [&](Index i) {
    Real s = 0;
    cf.for_each_neighbor(at[i], xf,
                         [&](Index, const Vec<D>&, Real r2) { s += W.value(std::sqrt(r2)); });
    if (G && cg && G->size() > 0)
      cg->for_each_neighbor(at[i], G->x, [&](Index g, const Vec<D>&, Real r2) {
        s += G->beta[g] * W.value(std::sqrt(r2));
      });
    n[i] = s;
  });
}

template <int D>
RelaxResult relax_particles(std::vector<Vec<D>>& x, const WallSet<D>& walls, CellList<D>& cells,
                            const WendlandC2<D>& W, const RelaxOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const Index n = static_cast<Index>(x.size());
  RelaxResult res;
  GhostSet<D> G;
  CellList<D> gcells;
  gcells.configure_like(cells, W.support);
  GhostOptions<D> gopt;
  gopt.map = opt.map;
  gopt.support = W.support;
  gopt.cells = &cells;
  const std::vector<Vec<D>> v0(x.size(), Vec<D>::Zero());
  std::vector<Real> nd(x.size());
  std::vector<Vec<D>> grad(x.size());
  const Real dx = static_cast<Real>(opt.dx);
  const Real h2 = W.h * W.h;
  const Real cap = static_cast<Real>(opt.max_shift) * dx;
  const double clearance = opt.wall_clearance * opt.dx;

  StageReport report("packing");
  for (long step = 0;; ++step) {
    cells.build(x);
    if (!walls.empty()) {
      G.build(x, v0, walls, gopt);
      gcells.build(G.x);
    }
    // n_i and grad n_i in one pass.
    parallel_for(n, [&](Index i) {
      Real s = 0;
      Vec<D> g = Vec<D>::Zero();
      cells.for_each_neighbor(x[i], x, [&](Index, const Vec<D>& r, Real r2) {
        const Real q = std::sqrt(r2);
        s += W.value(q);
        g += W.gradient_factor(q) * r;
      });
      if (G.size() > 0)
        gcells.for_each_neighbor(x[i], G.x, [&](Index k, const Vec<D>& r, Real r2) {
          const Real q = std::sqrt(r2);
          s += G.beta[k] * W.value(q);
          g += G.beta[k] * W.gradient_factor(q) * r;
        });
      nd[i] = s;
      grad[i] = g;
    });
    const double spread = relative_spread(nd);
    if (step == 0) res.spread_initial = spread;
    res.spread = spread;
    res.steps = step;
    if (spread < opt.tolerance || step >= opt.max_steps) {
      res.node_density = nd;
      report.result(
          fmt::format("{} steps, spread {:.3g} (tolerance {:.3g})", step, spread, opt.tolerance));
      break;
    }
    report.tick([&] {
      return fmt::format("step {}/{}, node-density spread {:.3g} -> {:.3g}", step, opt.max_steps,
                         spread, opt.tolerance);
    });
    double mean = 0;
    for (Real v : nd) mean += v;
    mean /= std::max<Index>(n, 1);
    const Real f = static_cast<Real>(opt.alpha) * h2 / static_cast<Real>(mean);
    parallel_for(n, [&](Index i) {
      pack_move<D>(x[i], -f * grad[i], cap);
      for (std::size_t k = 0; k < walls.size(); ++k) keep_clear_of<D>(x[i], walls[k], clearance);
      cells.wrap(x[i]);
    });
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

template void node_density<2>(const std::vector<Vec<2>>&, const std::vector<Vec<2>>&,
                              const CellList<2>&, const GhostSet<2>*, const CellList<2>*,
                              const WendlandC2<2>&, std::vector<Real>&);
template void node_density<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&,
                              const CellList<3>&, const GhostSet<3>*, const CellList<3>*,
                              const WendlandC2<3>&, std::vector<Real>&);
template RelaxResult relax_particles<2>(std::vector<Vec<2>>&, const WallSet<2>&, CellList<2>&,
                                        const WendlandC2<2>&, const RelaxOptions&);
template RelaxResult relax_particles<3>(std::vector<Vec<3>>&, const WallSet<3>&, CellList<3>&,
                                        const WendlandC2<3>&, const RelaxOptions&);

}  // namespace curvsph
