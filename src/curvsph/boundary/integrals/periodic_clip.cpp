#include "curvsph/boundary/integrals/periodic_clip.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace curvsph {

namespace {

template <int D>
bool centre_inside(const VecD<D>& c, const VecD<D>& lo, const VecD<D>& hi,
                   const std::array<bool, 3>& periodic) {
  for (int k = 0; k < D; ++k)
    if (periodic[static_cast<std::size_t>(k)] && (c[k] < lo[k] || c[k] >= hi[k])) return false;
  return true;
}

// Copies element j of `el` into `out` unchanged.
template <int D>
void copy_element(const BoundaryElements<D>& el, std::size_t j, BoundaryElements<D>& out) {
  out.centre.push_back(el.centre[j]);
  out.normal.push_back(el.normal[j]);
  out.area.push_back(el.area[j]);
  out.vertices.push_back(el.vertices[j]);
  out.vertex_count.push_back(el.vertex_count[j]);
  out.curvature.push_back(el.curvature[j]);
  out.gap.push_back(el.gap[j]);
}

}  // namespace

template <int D>
BoundaryElements<D> clip_to_periodic_domain(const BoundaryElements<D>& el, const VecD<D>& lo,
                                            const VecD<D>& hi,
                                            const std::array<bool, 3>& periodic) {
  BoundaryElements<D> out;
  for (std::size_t j = 0; j < el.size(); ++j) {
    const int m = el.vertex_count[j];
    bool whole = true;  // every vertex and the centre inside: nothing to cut
    for (int k = 0; k < D && whole; ++k) {
      if (!periodic[static_cast<std::size_t>(k)]) continue;
      for (int v = 0; v < m; ++v) {
        const double x = el.vertices[j][static_cast<std::size_t>(v)][k];
        whole = whole && x >= lo[k] && x <= hi[k];
      }
    }
    const bool flat = el.curvature[j] == 0.0 && el.gap[j] == 0.0;
    if (whole && centre_inside<D>(el.centre[j], lo, hi, periodic)) {
      copy_element(el, j, out);
      continue;
    }
    if (!flat) {
      if (centre_inside<D>(el.centre[j], lo, hi, periodic)) copy_element(el, j, out);
      continue;
    }
    // Flat: the polygon (2-D: the segment) clipped by the seam planes (Sutherland & Hodgman).
    std::vector<VecD<D>> poly(el.vertices[j].begin(), el.vertices[j].begin() + m);
    for (int k = 0; k < D; ++k) {
      if (!periodic[static_cast<std::size_t>(k)]) continue;
      for (const double sign : {1.0, -1.0}) {
        const double c = sign > 0 ? lo[k] : hi[k];
        std::vector<VecD<D>> next;
        const std::size_t n = poly.size();
        const std::size_t edges = D == 2 ? (n == 2 ? 1 : 0) : n;
        if (D == 2 && n == 2) {
          const VecD<D> a = poly[0], b = poly[1];
          const double fa = sign * (a[k] - c), fb = sign * (b[k] - c);
          if (fa >= 0 && fb >= 0) next = {a, b};
          if (fa >= 0 && fb < 0) next = {a, VecD<D>(a + (b - a) * (fa / (fa - fb)))};
          if (fa < 0 && fb >= 0) next = {VecD<D>(a + (b - a) * (fa / (fa - fb))), b};
        } else {
          for (std::size_t e = 0; e < edges; ++e) {
            const VecD<D>& s = poly[e];
            const VecD<D>& t = poly[(e + 1) % n];
            const double fs = sign * (s[k] - c), ft = sign * (t[k] - c);
            if (fs >= 0) next.push_back(s);
            if ((fs >= 0) != (ft >= 0)) next.push_back(s + (t - s) * (fs / (fs - ft)));
          }
        }
        poly = std::move(next);
      }
    }
    if constexpr (D == 2) {
      if (poly.size() == 2 &&
          (poly[1] - poly[0]).norm() > 1e-12 * (el.vertices[j][1] - el.vertices[j][0]).norm())
        out.add_segment(poly[0], poly[1]);
    } else {
      if (poly.size() < 3) continue;
      const double scale = std::sqrt(el.area[j]);
      auto add = [&](const VecD<D>* v, int count) {
        VecD<D> cr = VecD<D>::Zero();
        for (int i = 1; i + 1 < count; ++i) cr += (v[i] - v[0]).cross(v[i + 1] - v[0]);
        if (cr.norm() > 1e-12 * scale * scale) out.add_polygon(v, count);
      };
      if (poly.size() <= 4) {
        add(poly.data(), static_cast<int>(poly.size()));
      } else {
        for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
          const VecD<D> t[3] = {poly[0], poly[i], poly[i + 1]};
          add(t, 3);
        }
      }
    }
  }
  return out;
}

template BoundaryElements<2> clip_to_periodic_domain<2>(const BoundaryElements<2>&, const VecD<2>&,
                                                        const VecD<2>&, const std::array<bool, 3>&);
template BoundaryElements<3> clip_to_periodic_domain<3>(const BoundaryElements<3>&, const VecD<3>&,
                                                        const VecD<3>&, const std::array<bool, 3>&);

}  // namespace curvsph
