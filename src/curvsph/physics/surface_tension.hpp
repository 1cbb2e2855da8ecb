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
// image carries its source's colour (phase), mass and density, volume m_s/(rho_s beta_g).
// Its normal in the curvature sum is its source's unit normal, reflected across the wall
// (tangential part kept, normal part flipped: the mirrored interface) at walls without a
// contact angle, and copied unchanged at walls with one (the interface continued through the
// wall at the imposed angle; a reflection would put a kink of 180 - 2 theta at the contact
// line). Corner images (two or three reflections) enter the colour sum only. Between the two
// sums, particles near a wall with `contact_angle` get the turned normal of
// contact_angle.hpp, so the curvature, and the force, see the wetting condition.
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
  parallel_for(n, [&](Index i) {
    Vec<D> g = Vec<D>::Zero();
    if (in_pair(i)) {
      const Real ci = colour(i);
      cells.for_each_neighbor(P.x[i], P.x, [&](Index j, const Vec<D>& r, Real r2) {
        if (j == i || !in_pair(j)) return;
        const Real dc = colour(j) - ci;
        if (dc != 0) g += (P.mass[j] / P.rho[j]) * dc * W.gradient_factor(std::sqrt(r2)) * r;
      });
      if (images)
        G.cells->for_each_neighbor(P.x[i], *G.x, [&](Index k, const Vec<D>& r, Real r2) {
          const Index j = (*G.source)[k];
          if (!in_pair(j)) return;
          const Real dc = colour(j) - ci;
          if (dc != 0)
            g +=
                (P.mass[j] / (P.rho[j] * (*G.beta)[k])) * dc * W.gradient_factor(std::sqrt(r2)) * r;
        });
    }
    s.valid[i] = g.norm() > threshold;
    if (s.valid[i] && walls.walls && walls.angles && walls.layer > 0) {
      if (const auto cw = contact_wall<D>(*walls.walls, *walls.angles, P.x[i], walls.layer))
        g = contact_angle_normal<D>(g, cw->normal, cw->theta);
    }
    s.n[i] = g;
  });
  // Unit normal of image k: its source's, reflected at walls without a contact angle.
  auto image_normal = [&](Index k) -> Vec<D> {
    const Vec<D> nh = s.n[(*G.source)[k]].normalized();
    if (walls.angles && (*walls.angles)[static_cast<std::size_t>((*G.wall)[k])]) return nh;
    const Vec<D> nw = (*G.normal)[k].template cast<Real>();
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
        if (!s.valid[j] || !in_pair(j) || (*G.reflections)[k] != 1) return;
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
