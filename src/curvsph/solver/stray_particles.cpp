#include "curvsph/solver/stray_particles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/core/parallel.hpp"
#include "curvsph/geometry/box.hpp"

namespace curvsph {

template <int D>
long clamp_density(Particles<D>& P, Index n, const std::vector<Real>& rho0, Real lo, Real hi) {
  long count = 0;
#pragma omp parallel for reduction(+ : count) schedule(static)
  for (Index i = 0; i < n; ++i) {
    const Real r0 = rho0[static_cast<std::size_t>(P.phase[i])];
    const Real r = P.rho[i];
    if (!std::isfinite(r)) continue;  // NaN stays NaN: check_state stops the run
    if (r < lo * r0) {
      P.rho[i] = lo * r0;
      ++count;
    } else if (r > hi * r0) {
      P.rho[i] = hi * r0;
      ++count;
    }
  }
  return count;
}

template <int D>
WallFix project_out_of_walls(const WallSet<D>& walls, Vec<D>& x, Vec<D>& v, double depth) {
  WallFix fix = WallFix::none;
  for (int pass = 0; pass < 3; ++pass) {
    bool any = false;
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const Wall<D>& w = walls[k];
      const WallPoint<D> wp = w.closest(x.template cast<double>());
      if (!(wp.distance < depth)) continue;
      if (!(wp.distance > 0)) fix = WallFix::projected;
      if (fix == WallFix::none) fix = WallFix::contact;
      x = (wp.foot + depth * wp.normal).template cast<Real>();
      const Vec<D> n = wp.normal.template cast<Real>();
      const Vec<D> uw = w.velocity(wp.foot).template cast<Real>();
      const Real un = (v - uw).dot(n);
      if (un < 0) v -= un * n;  // only the part that carries it into the wall
      any = true;
    }
    if (!any) break;
  }
  return fix;
}

template <int D>
RemovalBox<D> removal_box(bool has_domain, const Vec3d& lo, const Vec3d& hi,
                          const std::array<bool, 3>& periodic, const std::vector<Vec<D>>& x,
                          const WallSet<D>& walls, double dx) {
  RemovalBox<D> r;
  r.periodic = periodic;
  if (has_domain) {
    r.box = Eigen::AlignedBox<double, D>(lo.head<D>(), hi.head<D>());
    return r;
  }
  for (const auto& p : x) r.box.extend(p.template cast<double>());
  // The fluid may reach any part of a tank: a box wall, and any other bounded wall (a
  // polygon, a circle, a CAD or STL solid) by the vertices of its boundary elements, which
  // lie on the exact wall. Coarse elements do (a twentieth of the particles' box; the box is
  // grown below by far more than a chord's sagitta), and the infinite walls (plane,
  // cylinder) are clipped to the particles' box, so they add nothing to it. Before, only box walls
  // counted: the water of a polygon tank running past its initial box by more than that box's size
  // was removed while inside the tank.
  for (std::size_t k = 0; k < walls.size(); ++k)
    if (const auto* b = dynamic_cast<const BoxWall<D>*>(&walls[k])) {
      r.box.extend(b->min());
      r.box.extend(b->max());
    }
  if (r.box.isEmpty()) r.box = Eigen::AlignedBox<double, D>(VecD<D>::Zero(), VecD<D>::Zero());
  {
    const Bounds<D> clip = r.box;
    const double spacing = std::max(r.box.sizes().maxCoeff() / 20, dx);
    Eigen::AlignedBox<double, D> extent = r.box;
    for (std::size_t k = 0; k < walls.size(); ++k) {
      BoundaryElements<D> el;
      try {
        el = elements_from_wall<D>(walls[k], spacing, clip);
      } catch (const std::invalid_argument&) {
        continue;  // a wall type without elements, or an infinite wall outside the box
      }
      for (std::size_t e = 0; e < el.size(); ++e)
        for (std::int32_t q = 0; q < el.vertex_count[e]; ++q)
          extent.extend(el.vertices[e][static_cast<std::size_t>(q)]);
    }
    r.box = extent;
  }
  const double grow = std::max(r.box.sizes().maxCoeff(), dx);
  r.box = Eigen::AlignedBox<double, D>(r.box.min().array() - grow, r.box.max().array() + grow);
  return r;
}

#define CURVSPH_INSTANTIATE(D)                                                                  \
  template long clamp_density<D>(Particles<D>&, Index, const std::vector<Real>&, Real, Real);   \
  template WallFix project_out_of_walls<D>(const WallSet<D>&, Vec<D>&, Vec<D>&, double);        \
  template RemovalBox<D> removal_box<D>(bool, const Vec3d&, const Vec3d&,                       \
                                        const std::array<bool, 3>&, const std::vector<Vec<D>>&, \
                                        const WallSet<D>&, double);
CURVSPH_INSTANTIATE(2)
CURVSPH_INSTANTIATE(3)
#undef CURVSPH_INSTANTIATE

}  // namespace curvsph
