#pragma once
// Surface tension by the continuum surface force of Brackbill, Kothe & Zemach (1992), in the
// SPH form of Morris (2000): for each pair of fluids (a, b) with coefficient s, the colour
// c = 1 on b and 0 on a,
//   n_i     = sum_j V_j (c_j - c_i) grad_i W_ij                      (colour gradient),
//   kappa_i = -[sum_j V_j (nh_j - nh_i).grad_i W_ij] / [sum_j V_j W_ij]  over j with a valid
//             normal (|n| > 0.01/h), nh = n/|n| — Morris's correction for the truncated sum,
//   a_i    += s kappa_i n_i / rho_i.
// n points from a into b; for a drop of b, kappa = 1/R > 0 and the force points into the drop,
// so the drop's pressure rises by s/R (Laplace). Particles of other fluids do not take part.
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph {

struct SurfaceTensionPair {
  int a = 0, b = 1;      // fluid indices
  Real coefficient = 0;  // N/m
};

template <int D>
struct SurfaceTensionScratch {
  std::vector<Vec<D>> n;
  std::vector<Real> kappa;
  std::vector<std::uint8_t> valid;
};

template <int D>
void add_surface_tension(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                         const SurfaceTensionPair& pair, SurfaceTensionScratch<D>& s) {
  const Index n = static_cast<Index>(P.size());
  s.n.resize(P.size());
  s.kappa.resize(P.size());
  s.valid.resize(P.size());
  const Real threshold = Real(0.01) / W.h;
  auto in_pair = [&](Index i) { return P.phase[i] == pair.a || P.phase[i] == pair.b; };
  auto colour = [&](Index i) { return P.phase[i] == pair.b ? Real(1) : Real(0); };
  parallel_for(n, [&](Index i) {
    Vec<D> g = Vec<D>::Zero();
    if (in_pair(i)) {
      const Real ci = colour(i);
      cells.for_each_neighbor(P.x[i], P.x, [&](Index j, const Vec<D>& r, Real r2) {
        if (j == i || !in_pair(j)) return;
        const Real dc = colour(j) - ci;
        if (dc != 0) g += (P.mass[j] / P.rho[j]) * dc * W.gradient_factor(std::sqrt(r2)) * r;
      });
    }
    s.n[i] = g;
    s.valid[i] = g.norm() > threshold;
  });
  parallel_for(n, [&](Index i) {
    s.kappa[i] = 0;
    if (!s.valid[i]) return;
    const Vec<D> nh_i = s.n[i].normalized();
    Real div = 0, weight = 0;
    cells.for_each_neighbor(P.x[i], P.x, [&](Index j, const Vec<D>& r, Real r2) {
      if (!s.valid[j] || !in_pair(j)) return;
      const Real rr = std::sqrt(r2);
      const Real Vj = P.mass[j] / P.rho[j];
      weight += Vj * W.value(rr);
      if (j != i) div += Vj * (s.n[j].normalized() - nh_i).dot(W.gradient_factor(rr) * r);
    });
    s.kappa[i] = weight > 0 ? -div / weight : 0;
  });
  parallel_for(n, [&](Index i) {
    if (s.valid[i]) P.a[i] += pair.coefficient * s.kappa[i] * s.n[i] / P.rho[i];
  });
}

}  // namespace curvsph
