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
//
// Walls (SurfaceTensionWalls). With a boundary model that builds wall images (ghosts), both
// sums run over the images too, with the same wall treatment as the density and forces: an
// image has its source's mass, density and volume m_s/(rho_s beta_g). At walls without a
// contact angle it carries its source's colour (phase) and its source's unit normal reflected
// across the wall (the mirrored interface). At walls with a contact angle it stands for the
// fluid at the point the continuation map sends onto it (the interface continued through the
// wall at the imposed angle, below) and carries that particle's colour and its normal continued
// by contact_angle_image_normal; mirror colours there would continue the interface at
// 180 - theta. Corner images (two or three reflections) enter the colour sum only. Between the
// two sums, particles within `layer` of a wall with `contact_angle` may get the turned normal
// of contact_angle.hpp (the solver passes layer 0: see kContactLayer).
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "curvsph/boundary/wall_images.hpp"
#include "curvsph/core/parallel.hpp"
#include "curvsph/core/particles.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"
#include "curvsph/physics/contact_angle.hpp"

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
  std::vector<Index> lookup;  // per wall image: the fluid particle it stands for
};

// Walls seen by surface tension: the geometry (contact angles, normals) and the wall images.
template <int D>
struct SurfaceTensionWalls {
  const WallSet<D>* walls = nullptr;
  const std::vector<std::optional<Real>>* angles = nullptr;  // per wall (parse_contact_angles)
  WallImages<D> images;
  Real layer = 0;  // contact-angle layer thickness (contact_angle.hpp); 0: no turning
};

template <int D>
void add_surface_tension(Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W,
                         const SurfaceTensionPair& pair, SurfaceTensionScratch<D>& s,
                         const SurfaceTensionWalls<D>& walls = {}) {
  const Index n = static_cast<Index>(P.size());
  s.n.resize(P.size());
  s.kappa.resize(P.size());
  s.valid.resize(P.size());
  const Real threshold = Real(0.01) / W.h;
  auto in_pair = [&](Index i) { return P.phase[i] == pair.a || P.phase[i] == pair.b; };
  auto colour = [&](Index i) { return P.phase[i] == pair.b ? Real(1) : Real(0); };
  const WallImages<D>& G = walls.images;
  const bool images = !G.empty();
  // Image k stands for the fluid particle s.lookup[k]: its source, except at walls with a
  // contact angle (below).
  const Index n_images = images ? static_cast<Index>(G.x->size()) : 0;
  if (images)
    s.lookup.assign(G.source->begin(), G.source->end());
  else
    s.lookup.clear();
  auto colour_gradient = [&](Index i) {
    Vec<D> g = Vec<D>::Zero();
    if (!in_pair(i)) return g;
    const Real ci = colour(i);
    cells.for_each_neighbor(P.x[i], P.x, [&](Index j, const Vec<D>& r, Real r2) {
      if (j == i || !in_pair(j)) return;
      const Real dc = colour(j) - ci;
      if (dc != 0) g += (P.mass[j] / P.rho[j]) * dc * W.gradient_factor(std::sqrt(r2)) * r;
    });
    if (images)
      G.cells->for_each_neighbor(P.x[i], *G.x, [&](Index k, const Vec<D>& r, Real r2) {
        const Index j = (*G.source)[k], l = s.lookup[k];
        if (!in_pair(j) || !in_pair(l)) return;
        const Real dc = colour(l) - ci;
        if (dc != 0)
          g += (P.mass[j] / (P.rho[j] * (*G.beta)[k])) * dc * W.gradient_factor(std::sqrt(r2)) * r;
      });
    return g;
  };
  parallel_for(n, [&](Index i) { s.n[i] = colour_gradient(i); });
  // Contact-angle walls: the interface continued through the wall at the imposed angle. The
  // map (x_t, d) -> (x_t + 2 d cot(theta), -d) in wall coordinates (t along t_w, away from the
  // drop; d the distance from the wall) takes the fluid side onto the wall's far side, keeps
  // the contact point, maps the straight interface at angle theta onto its own continuation,
  // and continues a circular arc with the same tangent and curvature (to second order; it is
  // the mirror map sheared along the wall, Jacobian -1). A mirror image at depth d beneath the
  // fluid point x_s therefore stands for the fluid at q = x_s - 2 d cot(theta) t_w, and takes
  // the colour (and, in the curvature sum, the normal) of the fluid particle nearest q. With
  // the plain mirror (the source's colour) the continued interface is the reflection of the
  // drop, at 180 - theta: the colour gradients of the second and third rows came out turned
  // by about 6 deg towards 90 deg on the exact 120 deg cap. t_w is the tangential part of the
  // source's colour gradient (first pass, mirror colours); images of sources without a valid
  // normal (beyond the kernel support of the interface) keep their source.
  if (images && walls.angles) {
    bool any = false;
    parallel_for(n_images, [&](Index k) {
      const auto& theta = (*walls.angles)[static_cast<std::size_t>((*G.wall)[k])];
      const Index src = (*G.source)[k];
      if (!theta || !in_pair(src) || !(s.n[src].norm() > threshold)) return;
      const Vec<D> nw = (*G.normal)[k].template cast<Real>();
      const Vec<D> m = -s.n[src];
      const Vec<D> tangential = m - m.dot(nw) * nw;
      if (!(tangential.norm() > Real(1e-12) * m.norm())) return;
      const Real depth = Real(0.5) * ((*G.x)[k] - P.x[src]).norm();
      const Vec<D> q = P.x[src] - 2 * depth / std::tan(*theta) * tangential.normalized();
      Real best = std::numeric_limits<Real>::infinity();
      Index l = src;
      cells.for_each_neighbor(q, P.x, [&](Index j, const Vec<D>&, Real r2) {
        if (in_pair(j) && r2 < best) {
          best = r2;
          l = j;
        }
      });
      s.lookup[k] = l;
    });
    for (Index k = 0; k < n_images && !any; ++k) any = s.lookup[k] != (*G.source)[k];
    if (any) parallel_for(n, [&](Index i) { s.n[i] = colour_gradient(i); });
  }
  parallel_for(n, [&](Index i) {
    Vec<D> g = s.n[i];
    s.valid[i] = g.norm() > threshold;
    if (s.valid[i] && walls.walls && walls.angles && walls.layer > 0) {
      if (const auto cw = contact_wall<D>(*walls.walls, *walls.angles, P.x[i], walls.layer))
        g = contact_angle_normal<D>(g, cw->normal, cw->theta);
    }
    s.n[i] = g;
  });
  // Unit normal of image k: that of the particle it stands for, reflected at walls without a
  // contact angle, continued across the wall at walls with one (contact_angle_image_normal).
  auto image_normal = [&](Index k) -> Vec<D> {
    const Vec<D> nh = s.n[s.lookup[k]].normalized();
    const Vec<D> nw = (*G.normal)[k].template cast<Real>();
    const auto& theta = walls.angles ? (*walls.angles)[static_cast<std::size_t>((*G.wall)[k])]
                                     : std::optional<Real>{};
    if (theta) return contact_angle_image_normal<D>(nh, nw, *theta);
    return nh - 2 * nh.dot(nw) * nw;
  };
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
    if (images)
      G.cells->for_each_neighbor(P.x[i], *G.x, [&](Index k, const Vec<D>& r, Real r2) {
        const Index j = (*G.source)[k];
        if (!s.valid[s.lookup[k]] || !in_pair(j) || (*G.reflections)[k] != 1) return;
        const Real rr = std::sqrt(r2);
        const Real Vk = P.mass[j] / (P.rho[j] * (*G.beta)[k]);
        weight += Vk * W.value(rr);
        div += Vk * (image_normal(k) - nh_i).dot(W.gradient_factor(rr) * r);
      });
    s.kappa[i] = weight > 0 ? -div / weight : 0;
  });
  parallel_for(n, [&](Index i) {
    if (s.valid[i]) P.a[i] += pair.coefficient * s.kappa[i] * s.n[i] / P.rho[i];
  });
}

}  // namespace curvsph
