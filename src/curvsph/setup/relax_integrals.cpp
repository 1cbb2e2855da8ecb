#include "curvsph/setup/relax_integrals.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/core/parallel.hpp"
#include "curvsph/core/stage_report.hpp"

namespace curvsph {

template <int D>
double integrals_residual(const std::vector<Vec<D>>& x, const CellList<D>& cells,
                          const std::vector<Vec<D>>& ex, const std::vector<Vec<D>>& en,
                          const std::vector<Real>& ea, const ElementQuadrature<D>& wq,
                          const CellList<D>& elem_cells, const WendlandC2<D>& W, Real volume,
                          std::vector<Vec<D>>& R) {
  const Index n = static_cast<Index>(x.size());
  R.resize(x.size());
  parallel_for(n, [&](Index i) {
    Vec<D> g = Vec<D>::Zero();
    // sum_j V_j grad_i W_ij, grad_i W_ij = r_ij (1/r) dW/dr, r_ij = x_i - x_j
    cells.for_each_neighbor(x[i], x, [&](Index j, const Vec<D>& r, Real r2) {
      if (j != i) g += volume * W.gradient_factor(std::sqrt(r2)) * r;
    });
    // - sum_b W_ib n_b A_b (= - grad gamma in the continuum)
    elem_cells.for_each_neighbor(x[i], ex, [&](Index b, const Vec<D>& r, Real) {
      g -= wq.mean_kernel(W, static_cast<std::size_t>(b), r) * ea[b] * en[b];
    });
    R[i] = g;
  });
  const Real m = parallel_max(n, Real(0), [&](Index i) { return R[i].norm(); });
  return static_cast<double>(W.h * m);
}

template <int D>
RelaxResult relax_particles_integrals(std::vector<Vec<D>>& x, const Wall<D>& closure,
                                      CellList<D>& cells, const WendlandC2<D>& W,
                                      const IntegralsRelaxOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  RelaxResult res;
  // Elements of the closure, clipped to the particles' bounding box grown by 4h (the
  // closure of a box region is finite; the bounds only matter for infinite walls).
  Bounds<D> bounds;
  for (const auto& p : x) bounds.extend(p.template cast<double>());
  const VecD<D> grow = VecD<D>::Constant(4 * static_cast<double>(W.h));
  bounds = Bounds<D>(bounds.min() - grow, bounds.max() + grow);
  const BoundaryElements<D> el = elements_from_wall<D>(closure, opt.dx, bounds);
  std::vector<Vec<D>> ex(el.size()), en(el.size());
  std::vector<Real> ea(el.size());
  double rmax = 0;
  for (std::size_t b = 0; b < el.size(); ++b) {
    ex[b] = el.centre[b].template cast<Real>();
    en[b] = el.normal[b].template cast<Real>();
    ea[b] = static_cast<Real>(el.area[b]);
    rmax = std::max(rmax, el.bounding_radius(b));
  }
  Vec3d lo = Vec3d::Zero(), hi = Vec3d::Zero();
  lo.head<D>() = bounds.min();
  hi.head<D>() = bounds.max();
  CellList<D> elem_cells;
  // Elements are found by centre within 2h + rmax; W_ib itself is cut at 2h.
  elem_cells.configure(W.support + static_cast<Real>(rmax), lo, hi, std::array<bool, 3>{});
  elem_cells.build(ex);
  const ElementQuadrature<D> wq = element_quadrature(el);

  const Real volume = static_cast<Real>(std::pow(opt.dx, D));
  const Real f = static_cast<Real>(opt.alpha) * W.h * W.h;
  const Real cap = static_cast<Real>(opt.max_shift * opt.dx);
  const double clearance = opt.wall_clearance * opt.dx;
  std::vector<Vec<D>> R;
  const Index n = static_cast<Index>(x.size());
  StageReport report("packing (integrals)");
  for (long step = 0;; ++step) {
    cells.build(x);
    const double r = integrals_residual<D>(x, cells, ex, en, ea, wq, elem_cells, W, volume, R);
    if (step == 0) res.spread_initial = r;
    res.spread = r;
    res.steps = step;
    if (r < opt.tolerance || step >= opt.max_steps) {
      report.result(
          fmt::format("{} steps, residual {:.3g} (tolerance {:.3g})", step, r, opt.tolerance));
      break;
    }
    report.tick([&] {
      return fmt::format("step {}/{}, BI residual {:.3g} -> {:.3g}", step, opt.max_steps, r,
                         opt.tolerance);
    });
    parallel_for(n, [&](Index i) {
      pack_move<D>(x[i], -f * R[i], cap);
      keep_clear_of<D>(x[i], closure, clearance);
      cells.wrap(x[i]);
    });
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

#define CURVSPH_RELAX_BI(D)                                                               \
  template double integrals_residual<D>(                                                  \
      const std::vector<Vec<D>>&, const CellList<D>&, const std::vector<Vec<D>>&,         \
      const std::vector<Vec<D>>&, const std::vector<Real>&, const ElementQuadrature<D>&,  \
      const CellList<D>&, const WendlandC2<D>&, Real, std::vector<Vec<D>>&);              \
  template RelaxResult relax_particles_integrals<D>(std::vector<Vec<D>>&, const Wall<D>&, \
                                                    CellList<D>&, const WendlandC2<D>&,   \
                                                    const IntegralsRelaxOptions&);
CURVSPH_RELAX_BI(2)
CURVSPH_RELAX_BI(3)
#undef CURVSPH_RELAX_BI

}  // namespace curvsph
