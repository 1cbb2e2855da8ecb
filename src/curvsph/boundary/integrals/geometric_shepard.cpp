// GeometricShepard: the geometric Shepard factor of a fixed element set, evaluated for every
// particle near a wall every step (the solver's path; shepard.hpp has the interface, and
// shepard.cpp the reference quadrature it is tested against).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/shepard_quadrature.hpp"
#include "curvsph/kernels/boundary_kernel.hpp"

namespace curvsph {

using shepard_detail::element_parts;
using shepard_detail::gauss_rule;
using shepard_detail::GaussRule;
using shepard_detail::geometric_impl;
using shepard_detail::point_in_polygon;
using shepard_detail::segment_distance;

template <>
void GeometricShepard<3>::build_patches(const BoundaryElements<3>& el);

template <int D>
GeometricShepard<D>::GeometricShepard(const BoundaryElements<D>& el, double h,
                                      const ShepardQuadrature& quad)
    : h_(h), quad_(quad) {
  radius_.resize(el.size());
  reach_.resize(el.size());
  for (std::size_t j = 0; j < el.size(); ++j) {
    radius_[j] = el.bounding_radius(j);
    reach_[j] = radius_[j];
    if constexpr (D == 3) {
      // A flat polygon whose centre projects into it (the centroid of a convex one):
      // d(x) <= |x - c'| <= |x - c| + |c - c'|, c' the centre's foot on the plane.
      const bool flat = j >= el.gap.size() || el.gap[j] == 0.0;
      const double off = std::abs(el.normal[j].dot(el.centre[j] - el.vertices[j][0]));
      if (flat && point_in_polygon(el, j, el.centre[j], 0.0)) reach_[j] = std::min(off, reach_[j]);
    }
  }
  if constexpr (D == 3) {
    // Twins: an edge b -> a of another element in the same plane with the same normal
    // cancels this element's a -> b term exactly (operator() below). Vertices are matched
    // on a grid of 1e-9 h.
    const double grid = 1e-9 * h;
    using Key = std::array<long long, 6>;
    auto key = [&](const Vec3d& a, const Vec3d& b) {
      Key k;
      for (int d = 0; d < 3; ++d) {
        k[static_cast<std::size_t>(d)] = std::llround(a[d] / grid);
        k[static_cast<std::size_t>(d + 3)] = std::llround(b[d] / grid);
      }
      return k;
    };
    std::map<Key, std::vector<std::int64_t>> edges;  // directed edge a -> b: elements
    twin_.assign(4 * el.size(), -1);
    for (std::size_t j = 0; j < el.size(); ++j) {
      const auto& v = el.vertices[j];
      const int m = el.vertex_count[j];
      for (int k = 0; k < m; ++k)
        edges[key(v[static_cast<std::size_t>(k)], v[static_cast<std::size_t>((k + 1) % m)])]
            .push_back(static_cast<std::int64_t>(j));
    }
    for (std::size_t j = 0; j < el.size(); ++j) {
      const auto& v = el.vertices[j];
      const int m = el.vertex_count[j];
      for (int k = 0; k < m; ++k) {
        const auto it = edges.find(
            key(v[static_cast<std::size_t>((k + 1) % m)], v[static_cast<std::size_t>(k)]));
        if (it == edges.end()) continue;
        for (std::int64_t o : it->second) {
          const auto so = static_cast<std::size_t>(o);
          const bool same_plane = (el.normal[so] - el.normal[j]).norm() < 1e-12 &&
                                  std::abs(el.normal[j].dot(el.vertices[so][0] - v[0])) < grid;
          if (same_plane && o != static_cast<std::int64_t>(j)) {
            twin_[4 * j + static_cast<std::size_t>(k)] = o;
            break;
          }
        }
      }
    }
    build_patches(el);
  }
}

namespace {

// Psi(q) = int_0^q F_Pext(s) s ds in units of h (3-D, DESIGN.md §4 kernel): inside the support
// the antiderivative of q h^3 F_P, outside of q / (4 pi q^3), continuous at q = 2.
inline double psi3(double q) {
  constexpr double pi = std::numbers::pi;
  if (q >= 2.0) return (0.375 - 0.25 / q) / pi;
  const double q2 = q * q;
  return ((((((3.0 / 1024.0 * q - 15.0 / 512.0) * q + 7.0 / 64.0) * q - 21.0 / 128.0) * q) * q) *
              q2 +
          7.0 / 32.0 * q2) /
         pi;
}

// The contribution 1 - gamma of a flat face that covers the whole support disc of x on its
// plane, x at distance delta = d/h (0 < delta < 2) on the fluid side. From the edge form in
// operator(): with F = F_D + F_Pext the radial antiderivative is Psi_full(q) = psi3(q) +
// 1/(4 pi q) (the singular part, h^3 F_D = -1/(4 pi q^3), gives +1/(4 pi q)), which is the
// constant 3/(8 pi) for q >= 2 (F = 0 there). A rim entirely outside the support therefore
// gives delta [Psi_full(delta) - 3/(8 pi)] times the angle it subtends about the foot, 2 pi:
//   1 - gamma = 1/2 - (3/4) delta + 2 pi delta psi3(delta).
// Checks: 1/2 at delta = 0 (on the wall), 0 at delta = 2 (psi3(2) = 1/(4 pi)), and
// d(gamma)/d(delta) = 3/4 at the wall = 2 pi int_0^2 W(q) q dq (the kernel's mass on the
// wall plane). Tested against the radial quadrature of tests/boundary/test_shepard.cpp.
inline double half_space_part(double delta) {
  return 0.5 - 0.75 * delta + 2.0 * std::numbers::pi * delta * psi3(delta);
}

// H(s_i) = [Psi(sqrt(d^2 + s_i)) - Psi0] / s_i at s_i = p^2 + t_i^2, t_i = t0 + x_i dl, for
// the n Gauss points x of one edge piece (the inner loop of the rim quadrature below, most
// of the geometric factor's cost). Two points at a time with SSE2 where available: the same
// IEEE operations in the same order as psi3 (both of its branches evaluated, one selected),
// so the values are bitwise those of the scalar loop; only the throughput of the square
// roots and divisions changes.
inline void rim_values(const double* x, std::size_t n, double t0, double dl, double p, double d2,
                       double psi0, double* out) {
  std::size_t i = 0;
#if defined(__SSE2__)
  constexpr double pi = std::numbers::pi;
  const __m128d vt0 = _mm_set1_pd(t0), vdl = _mm_set1_pd(dl), vp2 = _mm_set1_pd(p * p);
  const __m128d vd2 = _mm_set1_pd(d2), vpsi0 = _mm_set1_pd(psi0), vpi = _mm_set1_pd(pi);
  const __m128d two = _mm_set1_pd(2.0);
  for (; i + 1 < n; i += 2) {
    const __m128d t = _mm_add_pd(vt0, _mm_mul_pd(_mm_loadu_pd(x + i), vdl));
    const __m128d s = _mm_add_pd(vp2, _mm_mul_pd(t, t));
    const __m128d q = _mm_sqrt_pd(_mm_add_pd(vd2, s));
    const __m128d outer =
        _mm_div_pd(_mm_sub_pd(_mm_set1_pd(0.375), _mm_div_pd(_mm_set1_pd(0.25), q)), vpi);
    const __m128d q2 = _mm_mul_pd(q, q);
    __m128d in = _mm_sub_pd(_mm_mul_pd(_mm_set1_pd(3.0 / 1024.0), q), _mm_set1_pd(15.0 / 512.0));
    in = _mm_add_pd(_mm_mul_pd(in, q), _mm_set1_pd(7.0 / 64.0));
    in = _mm_sub_pd(_mm_mul_pd(in, q), _mm_set1_pd(21.0 / 128.0));
    in = _mm_mul_pd(_mm_mul_pd(_mm_mul_pd(in, q), q), q2);
    in = _mm_div_pd(_mm_add_pd(in, _mm_mul_pd(_mm_set1_pd(7.0 / 32.0), q2)), vpi);
    const __m128d far = _mm_cmpge_pd(q, two);
    const __m128d psi = _mm_or_pd(_mm_and_pd(far, outer), _mm_andnot_pd(far, in));
    _mm_storeu_pd(out + i, _mm_div_pd(_mm_sub_pd(psi, vpsi0), s));
  }
#endif
  for (; i < n; ++i) {
    const double t = t0 + x[i] * dl;
    const double s = p * p + t * t;
    out[i] = (psi3(std::sqrt(d2 + s)) - psi0) / s;
  }
}

}  // namespace

template <int D>
double GeometricShepard<D>::operator()(const BoundaryElements<D>& el,
                                       std::span<const std::size_t> candidates,
                                       const VecD<D>& x) const {
  const BoundaryKernel<D> F(h_);
  auto for_each = [&](const auto& fn) {
    for (std::size_t j : candidates) fn(j);
  };
  if constexpr (D == 2) {
    return geometric_impl<D>(
        el, x, h_, quad_, for_each, true,
        [&](std::span<const std::size_t> near, const Vec2d& y, const Vec2d& ys) {
          return element_parts(el, near, y, ys, F, quad_);
        },
        radius_.data());
  } else {
    // Polynomial part of a planar polygon, exact in the radial direction. With f the foot of
    // y on the polygon's plane, d = n.(v0 - y) and q-units (lengths / h):
    //   int_poly n.(z - y) F_Pext(|z - y|) dA = d sum_edges int_triangle(f, a, b)
    //   and int_triangle = int dtheta [Psi(sqrt(d^2 + rho_e^2)) - Psi(|d|)]
    // (polar coordinates about f, rho dr = u du), signed by the triangle's orientation, which
    // is Stokes' edge form of the area integral and holds wherever f lies. Along the edge
    // z = a + t e (e unit, p = the signed distance of f from the edge line), dtheta =
    // p dt / (p^2 + t^2), so each edge gives
    //   p int H(p^2 + t^2) dt,   H(s) = [Psi(sqrt(d^2 + s)) - Psi(|d|)] / s   (bounded, smooth)
    // with Gauss points on pieces split at the edge's closest point to f. An edge shared with
    // a twin of the same plane that is also among the elements cancels it exactly (the
    // reversed edge gives the opposite term): only the rim of the candidate patch of a flat
    // wall face is integrated.
    const GaussRule& g = gauss_rule(2 * quad_.gauss_points);
    std::array<double, 32> hv;  // H at the Gauss points of one piece (gauss_rule: n <= 32)
    const double inv_h = F.inv_h;
    const double max_piece = quad_.max_piece_over_h;  // in units of h
    constexpr double inv4pi = 0.25 / std::numbers::pi;
    // d [3/(8 pi) - psi3(|d|) - 1/(4 pi |d|)] per radian of edges 2h or more from the point
    // (depth d in h, psi0 = psi3(|d|)): the closed form of their contribution.
    auto far_edges = [&](double d, double psi0, double angle) {
      return (d * (1.5 * inv4pi - psi0) - std::copysign(inv4pi, d)) * angle;
    };
    // int H(p^2 + t^2) dt over [ta, tb] (q-units), in pieces split at t = 0 (the edge's closest
    // point to the foot), each no longer than max_piece.
    auto edge_integral = [&](double p, double ta, double tb, double d2, double psi0) {
      double cuts[3] = {ta, tb, tb};
      int ncut = 2;
      if (ta < 0.0 && tb > 0.0) {
        cuts[1] = 0.0;
        ncut = 3;
      }
      double edge = 0;
      for (int c = 0; c + 1 < ncut; ++c) {
        const double len = cuts[c + 1] - cuts[c];
        if (len <= 0) continue;
        const int pieces = std::max(1, static_cast<int>(std::ceil(len / max_piece)));
        const double dl = len / pieces;
        for (int pc = 0; pc < pieces; ++pc) {
          const double t0 = cuts[c] + pc * dl;
          rim_values(g.x.data(), g.x.size(), t0, dl, p, d2, psi0, hv.data());
          for (std::size_t i = 0; i < g.x.size(); ++i) edge += g.w[i] * dl * hv[i];
        }
      }
      return edge;
    };
    // Van Oosterom & Strackee: minus the solid angle of the triangle (ys, a, b) about the unit
    // vector fh from ys to its foot, a and b the unit vectors from ys to the edge's ends.
    auto solid_angle_term = [](const Vec3d& fh, const Vec3d& a, const Vec3d& b) {
      return -2.0 * std::atan2(fh.dot(a.cross(b)), 1.0 + fh.dot(a) + a.dot(b) + b.dot(fh));
    };
    auto parts = [&](std::span<const std::size_t> near, const Vec3d& y, const Vec3d& ys) {
      thread_local std::vector<std::uint32_t> mark;
      thread_local std::uint32_t stamp = 0;
      if (mark.size() != el.size()) {
        mark.assign(el.size(), 0);
        stamp = 0;
      }
      if (++stamp == 0) {
        std::fill(mark.begin(), mark.end(), 0);
        stamp = 1;
      }
      for (std::size_t j : near) mark[j] = stamp;
      // An edge wholly 2h or more from y (the rim of a patch is mostly made of them: an edge
      // whose twin is not near lies on that twin, at >= 2h) takes F = F_D + F_Pext = 0 beyond
      // the support: in the edge form below, p int [Psi_full(q) - Psi_full(|d|)] / (p^2 +
      // t^2) dt with Psi_full = psi3 + 1/(4 pi q) = 3/(8 pi) for q >= 2 (see half_space_part)
      // is [3/(8 pi) - Psi_full(|d|)] times the plane angle the edge subtends about the foot,
      // atan(tb/p) - atan(ta/p): no solid angle, no quadrature. Only where the singular and
      // polynomial parts are taken at the same point (ys = y, x not on a wall).
      const bool same_point = y == ys;
      const double support2 = 4.0 * h_ * h_;
      auto beyond = [&](const Vec3d& a, const Vec3d& b) {
        if (!same_point) return false;
        const Vec3d e = b - a;
        const double t = std::clamp(e.dot(y - a) / e.squaredNorm(), 0.0, 1.0);
        return (a + t * e - y).squaredNorm() >= support2;
      };
      // Solid angles: element j's is the signed sum of those of the triangles (f, a, b) over
      // its edges a -> b, f the foot of ys on its plane (Van Oosterom & Strackee with unit
      // vectors, signed as subtended_angle); twins cancel as for the polynomial part. A point
      // in the element's plane sees it under a zero angle (a point on it has been moved off
      // the wall by geometric_impl).
      double omega = 0;
      for (std::size_t j : near) {
        const Vec3d n = el.normal[j];
        const auto& v = el.vertices[j];
        const double ds = n.dot(v[0] - ys);
        if (std::abs(ds) <= 1e-14 * h_) continue;
        const Vec3d fh = ds > 0 ? n : Vec3d(-n);  // unit vector from ys to its foot
        const int m = el.vertex_count[j];
        for (int k = 0; k < m; ++k) {
          const std::int64_t tw = twin_[4 * j + static_cast<std::size_t>(k)];
          if (tw >= 0 && mark[static_cast<std::size_t>(tw)] == stamp) continue;
          if (beyond(v[static_cast<std::size_t>(k)], v[static_cast<std::size_t>((k + 1) % m)]))
            continue;  // in closed form below
          omega += solid_angle_term(fh, (v[static_cast<std::size_t>(k)] - ys).normalized(),
                                    (v[static_cast<std::size_t>((k + 1) % m)] - ys).normalized());
        }
      }
      double total = omega / (4 * std::numbers::pi);
      for (std::size_t j : near) {
        const Vec3d n = el.normal[j];
        const auto& v = el.vertices[j];
        const double dn = n.dot(v[0] - y);
        if (std::abs(dn) <= 1e-14 * h_) continue;  // y in the element's plane: n.(z - y) = 0
        const Vec3d f = y + dn * n;
        const double d = dn * inv_h, d2 = d * d, psi0 = psi3(std::abs(d));
        const int m = el.vertex_count[j];
        double sum = 0, far_angle = 0;
        for (int k = 0; k < m; ++k) {
          const std::int64_t tw = twin_[4 * j + static_cast<std::size_t>(k)];
          if (tw >= 0 && mark[static_cast<std::size_t>(tw)] == stamp) continue;
          const Vec3d& a = v[static_cast<std::size_t>(k)];
          const Vec3d& b = v[static_cast<std::size_t>((k + 1) % m)];
          const Vec3d e = (b - a).normalized();
          const double p = n.dot((a - f).cross(e)) * inv_h;
          if (p == 0.0) continue;
          const double ta = e.dot(a - f) * inv_h, tb = e.dot(b - f) * inv_h;
          if (beyond(a, b)) {
            far_angle += std::atan2(p * (tb - ta), p * p + ta * tb);  // exact difference
            continue;
          }
          sum += p * edge_integral(p, ta, tb, d2, psi0);
        }
        total += d * sum + far_edges(d, psi0, far_angle);
      }
      return total;
    };
    // Flat faces that cover the support disc of x (most particles near a wall): their
    // contribution in closed form (half_space_part), their elements skipped; a face whose
    // plane is 2h or more from x contributes nothing. Decided per patch (patch_, clear_):
    // the disc of radius rho = sqrt(4h^2 - d^2) about the foot f lies in the patch when
    // |f - c_j| + rho <= clear_[j] for any member j among the candidates. Everything else
    // (faces cut by their rim within the support, curved patches, points on or behind a
    // face) takes the rim quadrature above, which is additive over elements.
    struct Slot {
      std::int32_t patch;
      // pending: not yet known to cover the disc; cut: its rim crosses the disc (rim path).
      enum : unsigned char { none, pending, covered, cut, rest } state;
      double dn, rho;
      Vec3d foot, normal;
      // Rim path: d = signed depth in h (< 0 on the fluid side, as in `parts`), psi0 =
      // psi3(|d|); the sums of p int H dt, plane angles and solid-angle terms of the rim edges
      // within 2h; inside: the foot lies in the face.
      double d, psi0, poly, angle, omega;
      bool inside;
    };
    constexpr std::size_t max_slots = 16;
    std::array<Slot, max_slots> slots;
    std::size_t nslots = 0;
    const double support = 2.0 * h_;
    const double on_wall = 2.0 * quad_.on_wall_tolerance * h_;
    auto slot_of = [&](std::int32_t pid) -> Slot* {
      for (std::size_t k = 0; k < nslots; ++k)
        if (slots[k].patch == pid) return &slots[k];
      return nullptr;
    };
    // Candidates come cell by cell from the element cell list, so runs of them share a patch:
    // the last patch's slot is kept at hand instead of searching the slots for every element.
    // need_rest records whether anything is left for the quadrature; when nothing is (a
    // particle whose faces all cover its support, the common case), the second pass over the
    // candidates is skipped.
    std::int32_t last_pid = -1;
    Slot* last = nullptr;
    bool need_rest = false;
    for (std::size_t j : candidates) {
      const std::int32_t pid = patch_[j];
      if (pid < 0) {
        need_rest = true;
        continue;
      }
      Slot* s = pid == last_pid ? last : slot_of(pid);
      if (!s) {
        if (nslots == max_slots) {
          need_rest = true;
          continue;  // left to the quadrature (pass 2)
        }
        s = &slots[nslots++];
        s->patch = pid;
        s->dn = el.normal[j].dot(x - el.vertices[j][0]);  // > 0 on the fluid side
        if (std::abs(s->dn) >= support) {
          s->state = Slot::none;
        } else if (s->dn <= on_wall) {
          s->state = Slot::rest;  // on or behind the face: geometric_impl's limits
        } else {
          s->state = Slot::pending;
          s->rho = std::sqrt(support * support - s->dn * s->dn);
          s->foot = x - s->dn * el.normal[j];
          s->normal = el.normal[j];
          s->inside = false;
        }
      }
      last_pid = pid;
      last = s;
      if (s->state == Slot::pending) {
        const double room = clear_[j] - s->rho;
        const double fc2 = (s->foot - el.centre[j]).squaredNorm();
        if (room >= 0 && fc2 <= room * room) {
          s->state = Slot::covered;
        } else if (!s->inside && fc2 <= radius_[j] * radius_[j] &&
                   point_in_polygon(el, j, s->foot, 1e-9 * h_)) {
          // For the rim path: the foot lies in the face (its element is within the support,
          // hence among the candidates).
          s->inside = true;
        }
      }
    }
    double covered = 0;
    // The rim path needs ys = y in the element path's terms: no candidate that could put x on
    // a wall (outside any patch, left over by the slots, or a face x is on or behind).
    bool blocked = need_rest;
    bool any_pending = false;
    for (std::size_t k = 0; k < nslots; ++k) {
      Slot& sl = slots[k];
      if (sl.state == Slot::covered) covered += half_space_part(sl.dn * F.inv_h);
      if (sl.state == Slot::rest) blocked = true;
      if (sl.state == Slot::pending) any_pending = true;
    }
    bool any_cut = false;
    if (any_pending) {
      for (std::size_t k = 0; k < nslots; ++k) {
        Slot& sl = slots[k];
        if (sl.state != Slot::pending) continue;
        if (blocked || rim_start_.empty() || !patch_rim_ok_[static_cast<std::size_t>(sl.patch)]) {
          sl.state = Slot::rest;
          continue;
        }
        sl.state = Slot::cut;
        sl.d = -sl.dn * inv_h;
        sl.psi0 = psi3(std::abs(sl.d));
        sl.poly = sl.angle = sl.omega = 0;
        any_cut = true;
      }
    }
    if (any_cut) {
      // The rim edges within 2h of x, face by face. An edge 2h or more away adds only its
      // plane angle (see `parts`), and the angles of all edges left uncancelled by twins
      // among a face's elements within the support close to 2 pi about a foot inside the
      // face, 0 outside: so those far edges need not be visited. A foot on a rim edge (the
      // angles do not close there) sends the face to the element path.
      const double support2 = support * support;
      const double guard = 1e-6 * h_;
      int c0[3];
      for (int d = 0; d < 3; ++d) {
        const double r = std::floor((x[d] - rim_origin_[d]) / rim_cell_);
        c0[d] = static_cast<int>(
            std::clamp(r, -1.0, static_cast<double>(rim_dims_[static_cast<std::size_t>(d)])));
      }
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dxx = -1; dxx <= 1; ++dxx) {
            const int cx = c0[0] + dxx, cy = c0[1] + dy, cz = c0[2] + dz;
            if (cx < 0 || cy < 0 || cz < 0 || cx >= rim_dims_[0] || cy >= rim_dims_[1] ||
                cz >= rim_dims_[2])
              continue;
            const std::size_t cell = rim_cell_index(cx, cy, cz);
            for (std::uint32_t q = rim_start_[cell]; q < rim_start_[cell + 1]; ++q) {
              const RimEdge& e = rim_edges_[rim_index_[q]];
              // Edges of one cell mostly share a patch: keep the last slot at hand.
              if (e.patch != last_pid) {
                last = slot_of(e.patch);
                last_pid = e.patch;
              }
              Slot* s = last;
              if (!s || s->state != Slot::cut) continue;
              const Vec3d ev = e.b - e.a;
              const double t = std::clamp(ev.dot(x - e.a) / ev.squaredNorm(), 0.0, 1.0);
              if ((e.a + t * ev - x).squaredNorm() >= support2) continue;
              const Vec3d& f = s->foot;
              const Vec3d en = ev.normalized();
              const double p = s->normal.dot((e.a - f).cross(en)) * inv_h;
              // |p| h is the foot's distance from the edge's line, a lower bound of its
              // distance from the edge.
              if (std::abs(p) * h_ <= guard && segment_distance(e.a, e.b, f) <= guard) {
                s->state = Slot::rest;
                continue;
              }
              if (p != 0.0) {
                const double ta = en.dot(e.a - f) * inv_h, tb = en.dot(e.b - f) * inv_h;
                s->angle += std::atan2(p * (tb - ta), p * p + ta * tb);
                s->poly += p * edge_integral(p, ta, tb, s->d * s->d, s->psi0);
              }
              s->omega +=
                  solid_angle_term(-s->normal, (e.a - x).normalized(), (e.b - x).normalized());
            }
          }
    }
    // Left to the element path: everything `blocked` names, and the faces sent there above.
    need_rest = blocked;
    double cut = 0;
    for (std::size_t k = 0; k < nslots; ++k) {
      const Slot& sl = slots[k];
      if (sl.state == Slot::rest) need_rest = true;
      if (sl.state != Slot::cut) continue;
      const double far = (sl.inside ? 2 * std::numbers::pi : 0.0) - sl.angle;
      cut += sl.omega / (4 * std::numbers::pi) + sl.d * sl.poly + far_edges(sl.d, sl.psi0, far);
    }
    if (!need_rest) return 1.0 - covered - cut;
    thread_local std::vector<std::size_t> rest;
    rest.clear();
    last_pid = -1;
    last = nullptr;
    for (std::size_t j : candidates) {
      const std::int32_t pid = patch_[j];
      if (pid >= 0 && pid != last_pid) {
        last = slot_of(pid);
        last_pid = pid;
      }
      const Slot* s = pid < 0 ? nullptr : last;
      if (!s || s->state == Slot::rest) rest.push_back(j);
    }
    if (rest.empty()) return 1.0 - covered - cut;
    auto for_rest = [&](const auto& fn) {
      for (std::size_t j : rest) fn(j);
    };
    return geometric_impl<D>(el, x, h_, quad_, for_rest, true, parts, radius_.data(),
                             reach_.data()) -
           covered - cut;
  }
}

template class GeometricShepard<2>;
template class GeometricShepard<3>;

}  // namespace curvsph
