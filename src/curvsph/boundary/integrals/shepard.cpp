#include "curvsph/boundary/integrals/shepard.hpp"

// The Shepard factor's modes and the reference quadrature of the geometric one
// (shepard_geometric: element by element, Gauss points on the polynomial part); the solver's
// fast evaluation of the geometric factor is GeometricShepard (geometric_shepard.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "curvsph/boundary/integrals/shepard_quadrature.hpp"
#include "curvsph/kernels/boundary_kernel.hpp"
#include "curvsph/kernels/wendland.hpp"

namespace curvsph {

ShepardMode shepard_mode_from_string(std::string_view name) {
  if (name == "geometric") return ShepardMode::geometric;
  if (name == "monolithic") return ShepardMode::monolithic;
  if (name == "volume") return ShepardMode::volume;
  if (name == "none") return ShepardMode::none;
  throw std::invalid_argument("unknown Shepard mode '" + std::string(name) +
                              "' (expected geometric | monolithic | volume | none)");
}

const char* to_string(ShepardMode mode) {
  switch (mode) {
    case ShepardMode::geometric:
      return "geometric";
    case ShepardMode::monolithic:
      return "monolithic";
    case ShepardMode::volume:
      return "volume";
    case ShepardMode::none:
      return "none";
  }
  return "?";
}

namespace shepard_detail {

const GaussRule& gauss_rule(int n) {
  // One once_flag per rule rather than a mutex: the solver asks for the rule for every
  // particle near a wall, every step, and after the first call this is a lock-free check.
  static std::array<std::once_flag, 33> once;
  static std::array<GaussRule, 33> cache;
  n = std::clamp(n, 1, 32);
  GaussRule& r = cache[static_cast<std::size_t>(n)];
  std::call_once(once[static_cast<std::size_t>(n)], [&] {
    r.x.resize(static_cast<std::size_t>(n));
    r.w.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 1;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = 0;
        for (int k = 1; k <= n; ++k) {
          const double p2 = p1;
          p1 = p0;
          p0 = ((2 * k - 1) * z * p1 - (k - 1) * p2) / k;
        }
        dp = n * (z * p0 - p1) / (z * z - 1);
        const double dz = p0 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      r.x[static_cast<std::size_t>(i)] = 0.5 * (1 - z);
      r.w[static_cast<std::size_t>(i)] = 1.0 / ((1 - z * z) * dp * dp);  // 2/((1-z^2)P'^2) / 2
    }
  });
  return r;
}

bool point_in_polygon(const BoundaryElements<3>& el, std::size_t j, const Vec3d& p, double tol) {
  const auto& v = el.vertices[j];
  const int m = el.vertex_count[j];
  for (int k = 0; k < m; ++k) {
    const Vec3d& a = v[static_cast<std::size_t>(k)];
    const Vec3d& b = v[static_cast<std::size_t>((k + 1) % m)];
    const Vec3d e = b - a;
    if (e.cross(p - a).dot(el.normal[j]) < -tol * e.norm()) return false;
  }
  return true;
}

double segment_distance(const Vec3d& a, const Vec3d& b, const Vec3d& x) {
  const Vec3d e = b - a;
  const double t = std::clamp(e.dot(x - a) / e.squaredNorm(), 0.0, 1.0);
  return (a + t * e - x).norm();
}

double element_distance(const BoundaryElements<2>& el, std::size_t j, const Vec2d& x) {
  const Vec2d& a = el.vertices[j][0];
  const Vec2d& b = el.vertices[j][1];
  const double kappa = el.curvature[j];
  const double end = std::min((x - a).norm(), (x - b).norm());
  if (kappa == 0.0) {
    const Vec2d e = b - a;
    const double t = std::clamp(e.dot(x - a) / e.squaredNorm(), 0.0, 1.0);
    return (a + t * e - x).norm();
  }
  const Vec2d O = arc_circle_centre(el, j);
  const double R = 1.0 / std::abs(kappa);
  const double r = (x - O).norm();
  if (r == 0.0) return R;
  const Vec2d y = O + (x - O) * (R / r);
  const double side = el.normal[j].dot(y - a);
  const bool on_arc = kappa > 0 ? side <= 0 : side >= 0;
  return on_arc ? std::abs(r - R) : end;
}

double element_distance(const BoundaryElements<3>& el, std::size_t j, const Vec3d& x) {
  const auto& v = el.vertices[j];
  const double s = el.normal[j].dot(x - v[0]);
  const Vec3d p = x - s * el.normal[j];
  if (point_in_polygon(el, j, p, 0.0)) return std::abs(s);
  double d = std::numeric_limits<double>::infinity();
  const int m = el.vertex_count[j];
  for (int k = 0; k < m; ++k)
    d = std::min(d, segment_distance(v[static_cast<std::size_t>(k)],
                                     v[static_cast<std::size_t>((k + 1) % m)], x));
  return d;
}

double signed_offset(const BoundaryElements<2>& el, std::size_t j, const Vec2d& x, bool& onto) {
  const Vec2d& a = el.vertices[j][0];
  const Vec2d& b = el.vertices[j][1];
  const double kappa = el.curvature[j];
  if (kappa == 0.0) {
    const Vec2d e = b - a;
    const double t = e.dot(x - a) / e.squaredNorm();
    onto = t >= 0.0 && t <= 1.0;
    return el.normal[j].dot(x - a);
  }
  const Vec2d O = arc_circle_centre(el, j);
  const double R = 1.0 / std::abs(kappa), r = (x - O).norm();
  onto = r > 0.0 && el.normal[j].dot(O + (x - O) * (R / r) - a) * kappa <= 0.0;
  return kappa > 0 ? R - r : r - R;
}

double signed_offset(const BoundaryElements<3>& el, std::size_t j, const Vec3d& x, bool& onto) {
  const auto& v = el.vertices[j];
  const int m = el.vertex_count[j];
  Vec3d pn = Vec3d::Zero();
  for (int k = 1; k + 1 < m; ++k)
    pn += (v[static_cast<std::size_t>(k)] - v[0]).cross(v[static_cast<std::size_t>(k + 1)] - v[0]);
  pn.normalize();
  const double s = pn.dot(x - v[0]);
  // Within the gap beyond an edge too: the wall between two vertices of a curved edge (a
  // CAD face's seam) bulges past the edge's chord, over no element.
  const double g = j < el.gap.size() ? el.gap[j] : 0.0;
  onto = point_in_polygon(el, j, x - s * pn, g);
  return s;
}

// ---- Polynomial part: int_j n(y).(y - x) F_Pext(|y - x|) dy -----------------------------

double poly_part(const BoundaryElements<2>& el, std::size_t j, const Vec2d& x,
                 const BoundaryKernel<2>& F, const ShepardQuadrature& q) {
  const GaussRule& g = gauss_rule(q.gauss_points);
  const Vec2d& a = el.vertices[j][0];
  const Vec2d& b = el.vertices[j][1];
  const Vec2d n = el.normal[j];
  const double kappa = el.curvature[j];
  const double L = el.area[j];
  const double max_piece = q.max_piece_over_h * F.h;
  const Vec2d t = (b - a).normalized();
  double s_lo, s_hi, s_foot;
  if (kappa == 0.0) {
    const double dn = n.dot(a - x);
    if (std::abs(dn) <= 1e-14 * F.h) return 0.0;  // x on the element's line
    s_lo = 0;
    s_hi = (b - a).norm();
    s_foot = t.dot(x - a);
  } else {
    s_lo = -0.5 * L;
    s_hi = 0.5 * L;
    s_foot = t.dot(x - el.centre[j]);
  }
  const Vec2d c = el.centre[j];
  auto integrand = [&](double s) {
    if (kappa == 0.0) {
      const Vec2d y = a + s * t;
      return n.dot(y - x) * F.polynomial_extended((y - x).norm());
    }
    // y(s) = O + (c - O) cos(s k) + t sin(s k)/k with c - O = -n/k; n(s) = (O - y) k.
    const double cs = std::cos(s * kappa), sn = std::sin(s * kappa);
    const Vec2d y = c + n * ((1.0 - cs) / kappa) + t * (sn / kappa);
    const Vec2d ns = n * cs - t * sn;
    return ns.dot(y - x) * F.polynomial_extended((y - x).norm());
  };
  double cuts[3] = {s_lo, s_hi, s_hi};
  int ncut = 2;
  if (s_foot > s_lo && s_foot < s_hi) {
    cuts[1] = s_foot;
    cuts[2] = s_hi;
    ncut = 3;
  }
  double sum = 0;
  for (int p = 0; p + 1 < ncut; ++p) {
    const double len = cuts[p + 1] - cuts[p];
    if (len <= 0) continue;
    const int m = std::max(1, static_cast<int>(std::ceil(len / max_piece)));
    const double dl = len / m;
    for (int k = 0; k < m; ++k) {
      const double s0 = cuts[p] + k * dl;
      for (std::size_t i = 0; i < g.x.size(); ++i) sum += g.w[i] * dl * integrand(s0 + g.x[i] * dl);
    }
  }
  return sum;
}

namespace {

// int over triangle (p0, p1, p2) of f, collapsed (Duffy) Gauss rule with p0 the collapsed
// vertex, sub-divided until the longest edge is <= max_edge.
template <class Fn>
double triangle_integral(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2, double max_edge,
                         const GaussRule& g, const Fn& f, int depth = 0) {
  const double longest = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm()});
  if (longest > max_edge && depth < 8) {
    const Vec3d m01 = 0.5 * (p0 + p1), m12 = 0.5 * (p1 + p2), m20 = 0.5 * (p2 + p0);
    return triangle_integral(p0, m01, m20, max_edge, g, f, depth + 1) +
           triangle_integral(m01, p1, m12, max_edge, g, f, depth + 1) +
           triangle_integral(m20, m12, p2, max_edge, g, f, depth + 1) +
           triangle_integral(m12, m20, m01, max_edge, g, f, depth + 1);
  }
  const double twice_area = (p1 - p0).cross(p2 - p0).norm();
  if (twice_area <= 0) return 0.0;
  double sum = 0;
  for (std::size_t i = 0; i < g.x.size(); ++i) {
    const double u = g.x[i];
    for (std::size_t k = 0; k < g.x.size(); ++k) {
      const double w = g.x[k];
      const Vec3d y = p0 + u * (p1 - p0) + u * w * (p2 - p1);
      sum += g.w[i] * g.w[k] * u * f(y);
    }
  }
  return sum * twice_area;
}

}  // namespace

double poly_part(const BoundaryElements<3>& el, std::size_t j, const Vec3d& x,
                 const BoundaryKernel<3>& F, const ShepardQuadrature& q) {
  const Vec3d n = el.normal[j];
  const auto& v = el.vertices[j];
  const int m = el.vertex_count[j];
  const double dn = n.dot(v[0] - x);
  if (std::abs(dn) <= 1e-14 * F.h) return 0.0;
  const GaussRule& g = gauss_rule(q.gauss_points);
  auto f = [&](const Vec3d& y) { return F.polynomial_extended((y - x).norm()); };
  const double max_edge = q.max_piece_over_h * F.h;
  const Vec3d foot = x + dn * n;
  double sum = 0;
  if (point_in_polygon(el, j, foot, 1e-12 * F.h)) {
    for (int k = 0; k < m; ++k)
      sum += triangle_integral(foot, v[static_cast<std::size_t>(k)],
                               v[static_cast<std::size_t>((k + 1) % m)], max_edge, g, f);
  } else {
    for (int k = 1; k + 1 < m; ++k)
      sum += triangle_integral(v[0], v[static_cast<std::size_t>(k)],
                               v[static_cast<std::size_t>(k + 1)], max_edge, g, f);
  }
  return dn * sum;
}

}  // namespace shepard_detail

using shepard_detail::arc_circle_centre;
using shepard_detail::cross2;
using shepard_detail::element_distance;
using shepard_detail::element_parts;
using shepard_detail::geometric_impl;
using shepard_detail::pi;

template <>
double subtended_angle<2>(const BoundaryElements<2>& el, std::size_t j, const Vec2d& x) {
  const Vec2d& a = el.vertices[j][0];
  const Vec2d& b = el.vertices[j][1];
  const Vec2d u = a - x, w = b - x;
  const double theta = std::atan2(std::abs(cross2(u, w)), u.dot(w));
  const double side = el.normal[j].dot(x - a);
  double angle = side >= 0 ? theta : -theta;
  const double kappa = el.curvature[j];
  if (kappa != 0.0) {
    // x between the chord and the arc: the arc wraps around x the other way.
    const Vec2d O = arc_circle_centre(el, j);
    const bool inside_circle = (x - O).norm() < 1.0 / std::abs(kappa);
    if (inside_circle && (kappa > 0 ? side < 0 : side > 0)) angle += kappa > 0 ? 2 * pi : -2 * pi;
  }
  return angle;
}

template <>
double subtended_angle<3>(const BoundaryElements<3>& el, std::size_t j, const Vec3d& x) {
  const auto& v = el.vertices[j];
  const int m = el.vertex_count[j];
  const Vec3d a = (v[0] - x).normalized();
  double omega = 0;
  for (int k = 1; k + 1 < m; ++k) {
    const Vec3d b = (v[static_cast<std::size_t>(k)] - x).normalized();
    const Vec3d c = (v[static_cast<std::size_t>(k + 1)] - x).normalized();
    // Van Oosterom & Strackee with unit vectors; the vertices run counter-clockwise seen
    // from the fluid, so a.(b x c) < 0 there: the minus sign makes the fluid side positive.
    omega -= 2.0 * std::atan2(a.dot(b.cross(c)), 1.0 + a.dot(b) + b.dot(c) + c.dot(a));
  }
  return omega;
}

template <int D>
double shepard_geometric(const BoundaryElements<D>& el, const VecD<D>& x, double h,
                         const ShepardQuadrature& quad) {
  const BoundaryKernel<D> F(h);
  return geometric_impl<D>(
      el, x, h, quad,
      [&](const auto& fn) {
        for (std::size_t j = 0; j < el.size(); ++j) fn(j);
      },
      false,
      [&](std::span<const std::size_t> near, const VecD<D>& y, const VecD<D>& ys) {
        return element_parts(el, near, y, ys, F, quad);
      });
}

template <int D>
double shepard_geometric(const BoundaryElements<D>& el, std::span<const std::size_t> candidates,
                         const VecD<D>& x, double h, const ShepardQuadrature& quad) {
  const BoundaryKernel<D> F(h);
  return geometric_impl<D>(
      el, x, h, quad,
      [&](const auto& fn) {
        for (std::size_t j : candidates) fn(j);
      },
      false,
      [&](std::span<const std::size_t> near, const VecD<D>& y, const VecD<D>& ys) {
        return element_parts(el, near, y, ys, F, quad);
      });
}

namespace {

template <int D, class ForEach>
double monolithic_impl(const BoundaryElements<D>& el, const VecD<D>& x, double h,
                       const ShepardQuadrature& quad, const ForEach& for_each) {
  const BoundaryKernel<D> F(h);
  const double tol = quad.on_wall_tolerance * h;
  double sum = 0;
  bool on_contour = false;
  for_each([&](std::size_t j) {
    const VecD<D> r = el.centre[j] - x;
    const double rn = r.norm();
    if (rn - el.bounding_radius(j) >= 2.0 * h) return;
    if (quad.monolithic_contour_half && element_distance(el, j, x) <= tol) {
      on_contour = true;  // the element x lies on: replaced by the exact -1/2 below
      return;
    }
    if (rn >= 2.0 * h || rn <= 1e-12 * h) return;
    sum += el.normal[j].dot(r) * F.value(rn) * el.area[j];
  });
  return 1.0 - sum - (on_contour ? 0.5 : 0.0);
}

}  // namespace

template <int D>
double shepard_monolithic(const BoundaryElements<D>& el, const VecD<D>& x, double h,
                          const ShepardQuadrature& quad) {
  return monolithic_impl<D>(el, x, h, quad, [&](const auto& fn) {
    for (std::size_t j = 0; j < el.size(); ++j) fn(j);
  });
}

template <int D>
double shepard_monolithic(const BoundaryElements<D>& el, std::span<const std::size_t> candidates,
                          const VecD<D>& x, double h, const ShepardQuadrature& quad) {
  return monolithic_impl<D>(el, x, h, quad, [&](const auto& fn) {
    for (std::size_t j : candidates) fn(j);
  });
}

template <int D>
double shepard_volume(std::span<const VecD<D>> positions, std::span<const double> volumes,
                      const VecD<D>& x, double h) {
  if (positions.size() != volumes.size())
    throw std::invalid_argument("shepard_volume: positions and volumes differ in size");
  const WendlandC2<D> W(static_cast<Real>(h));
  const double s2 = 4.0 * h * h;
  double sum = 0;
  for (std::size_t j = 0; j < positions.size(); ++j) {
    const double r2 = (positions[j] - x).squaredNorm();
    if (r2 < s2) sum += static_cast<double>(W.value(static_cast<Real>(std::sqrt(r2)))) * volumes[j];
  }
  return sum;
}

template <int D>
std::vector<double> shepard_factor(ShepardMode mode, const BoundaryElements<D>& el,
                                   std::span<const VecD<D>> points, double h,
                                   std::span<const VecD<D>> fluid_positions,
                                   std::span<const double> fluid_volumes,
                                   const ShepardQuadrature& quad) {
  std::vector<double> out(points.size(), 1.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    switch (mode) {
      case ShepardMode::geometric:
        out[i] = shepard_geometric<D>(el, points[i], h, quad);
        break;
      case ShepardMode::monolithic:
        out[i] = shepard_monolithic<D>(el, points[i], h, quad);
        break;
      case ShepardMode::volume:
        out[i] = shepard_volume<D>(fluid_positions, fluid_volumes, points[i], h);
        break;
      case ShepardMode::none:
        break;
    }
  }
  return out;
}

#define CURVSPH_SHEPARD_INSTANTIATE(D)                                                            \
  template double shepard_geometric<D>(const BoundaryElements<D>&, const VecD<D>&, double,        \
                                       const ShepardQuadrature&);                                 \
  template double shepard_monolithic<D>(const BoundaryElements<D>&, const VecD<D>&, double,       \
                                        const ShepardQuadrature&);                                \
  template double shepard_geometric<D>(const BoundaryElements<D>&, std::span<const std::size_t>,  \
                                       const VecD<D>&, double, const ShepardQuadrature&);         \
  template double shepard_monolithic<D>(const BoundaryElements<D>&, std::span<const std::size_t>, \
                                        const VecD<D>&, double, const ShepardQuadrature&);        \
  template double shepard_volume<D>(std::span<const VecD<D>>, std::span<const double>,            \
                                    const VecD<D>&, double);                                      \
  template std::vector<double> shepard_factor<D>(                                                 \
      ShepardMode, const BoundaryElements<D>&, std::span<const VecD<D>>, double,                  \
      std::span<const VecD<D>>, std::span<const double>, const ShepardQuadrature&);
CURVSPH_SHEPARD_INSTANTIATE(2)
CURVSPH_SHEPARD_INSTANTIATE(3)
template class GeometricShepard<2>;
template class GeometricShepard<3>;
#undef CURVSPH_SHEPARD_INSTANTIATE

}  // namespace curvsph