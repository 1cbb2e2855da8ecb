#include "curvsph/boundary/integrals/wall_elements.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "curvsph/boundary/integrals/wall_elements_freeform.hpp"
#include "curvsph/core/quadrature.hpp"
#include "curvsph/geometry/box.hpp"
#include "curvsph/geometry/circle.hpp"
#include "curvsph/geometry/cylinder.hpp"
#include "curvsph/geometry/ellipse.hpp"
#include "curvsph/geometry/moving_wall.hpp"
#include "curvsph/geometry/plane.hpp"
#include "curvsph/geometry/shape_util.hpp"
#include "curvsph/geometry/sphere.hpp"
#include "curvsph/geometry/torus.hpp"

namespace curvsph {

namespace wall_elements_detail {

// ---- Curved patches (3-D) ------------------------------------------------------------------

// wall_elements_freeform.hpp describes it.
void add_surface_cell(BoundaryElements<3>& out, const std::function<Vec3d(double, double)>& S,
                      const std::function<Vec3d(double, double)>& normal, double u0, double u1,
                      double v0, double v1, double area) {
  const std::array<Vec3d, 4> corners = {S(u0, v0), S(u1, v0), S(u1, v1), S(u0, v1)};
  std::array<Vec3d, 4> v;
  int count = 0;
  const double scale = (corners[2] - corners[0]).norm() + (corners[3] - corners[1]).norm();
  for (const Vec3d& p : corners) {
    bool duplicate = false;
    for (int k = 0; k < count; ++k)
      duplicate = duplicate || (v[static_cast<std::size_t>(k)] - p).norm() <= 1e-12 * scale;
    if (!duplicate) v[static_cast<std::size_t>(count++)] = p;
  }
  if (count < 3) return;
  const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
  const Vec3d c = S(um, vm), n = normal(um, vm);
  Vec3d pn = Vec3d::Zero();
  for (int k = 1; k + 1 < count; ++k)
    pn += (v[static_cast<std::size_t>(k)] - v[0]).cross(v[static_cast<std::size_t>(k + 1)] - v[0]);
  if (pn.dot(n) < 0) std::reverse(v.begin(), v.begin() + count);
  pn = pn.normalized();
  // Largest distance of the surface from the polygon's plane (centre and edge midpoints), and
  // of the vertices (a quad of a doubly curved surface need not be planar).
  double g = std::abs(pn.dot(c - v[0]));
  for (int k = 1; k < count; ++k)
    g = std::max(g, std::abs(pn.dot(v[static_cast<std::size_t>(k)] - v[0])));
  for (const auto& [a, b] : {std::pair{um, v0}, {um, v1}, {u0, vm}, {u1, vm}})
    g = std::max(g, std::abs(pn.dot(S(a, b) - v[0])));
  out.add_curved_patch(v.data(), count, c, n, area, 1.5 * g);
}

}  // namespace wall_elements_detail

namespace {

constexpr double pi = std::numbers::pi;

int count_for(double length, double dx, int minimum) {
  return std::max(minimum, static_cast<int>(std::lround(length / dx)));
}

void require_bounds(const auto& bounds, const std::string& what) {
  if (bounds.isEmpty())
    throw std::invalid_argument("boundary elements of an infinite wall (" + what +
                                ") need domain bounds");
}

using wall_elements_detail::add_surface_cell;

// ---- 2-D walls -------------------------------------------------------------------------------

bool plane_2d(const Wall<2>& w, double dx, const Bounds<2>& bounds, BoundaryElements<2>& out) {
  const auto* p = dynamic_cast<const PlaneWall<2>*>(&w);
  if (!p) return false;
  require_bounds(bounds, w.describe());
  const Vec2d n = p->normal(), t(n.y(), -n.x());  // fluid on the left of t
  double s0 = -std::numeric_limits<double>::infinity(), s1 = -s0;
  for (int i = 0; i < 2; ++i) {
    const double o = p->point()[i];
    if (std::abs(t[i]) < 1e-300) {
      if (o < bounds.min()[i] || o > bounds.max()[i]) return true;  // misses the domain
      continue;
    }
    double a = (bounds.min()[i] - o) / t[i], b = (bounds.max()[i] - o) / t[i];
    if (a > b) std::swap(a, b);
    s0 = std::max(s0, a);
    s1 = std::min(s1, b);
  }
  if (!(s1 > s0)) return true;
  const Vec2d A = p->point() + s0 * t, B = p->point() + s1 * t;
  const int m = count_for(s1 - s0, dx, 1);
  for (int k = 0; k < m; ++k)
    out.add_segment(A + (B - A) * (double(k) / m), A + (B - A) * (double(k + 1) / m));
  return true;
}

bool box_2d(const Wall<2>& w, double dx, const Bounds<2>&, BoundaryElements<2>& out) {
  const auto* b = dynamic_cast<const BoxWall<2>*>(&w);
  if (!b) return false;
  const Vec2d lo = b->min(), hi = b->max();
  std::vector<Vec2d> pts = {lo, Vec2d(hi.x(), lo.y()), hi, Vec2d(lo.x(), hi.y())};
  if (b->side() == FluidSide::outside) std::reverse(pts.begin(), pts.end());
  out.append(polyline_elements(pts, dx, true));
  return true;
}

bool circle_2d(const Wall<2>& w, double dx, const Bounds<2>&, BoundaryElements<2>& out) {
  const auto* c = dynamic_cast<const CircleWall*>(&w);
  if (!c) return false;
  out.append(circle_elements(c->center(), c->radius(), dx, c->side() == FluidSide::inside));
  return true;
}

// Eccentric angle u > u0 with arc length s from u0 (Newton; |C'| > 0 everywhere).
double ellipse_angle_at(double a, double b, double u0, double s) {
  auto speed = [&](double u) { return std::hypot(a * std::sin(u), b * std::cos(u)); };
  double u = u0 + s / speed(u0);
  for (int it = 0; it < 50; ++it) {
    const double f = ellipse_arc_length(a, b, u0, u) - s;
    const double du = f / speed(u);
    u -= du;
    if (std::abs(du) < 1e-15 * (1.0 + std::abs(u))) break;
  }
  return u;
}

bool ellipse_2d(const Wall<2>& w, double dx, const Bounds<2>&, BoundaryElements<2>& out) {
  const auto* e = dynamic_cast<const EllipseWall*>(&w);
  if (!e) return false;
  const double a = e->semi_axis_a(), b = e->semi_axis_b();
  const Vec2d O = e->center();
  const bool inside = e->side() == FluidSide::inside;
  auto C = [&](double u) { return Vec2d(O.x() + a * std::cos(u), O.y() + b * std::sin(u)); };
  const double perimeter = ellipse_arc_length(a, b, 0.0, 2 * pi);
  const int m = count_for(perimeter, dx, 3);
  const double ds = perimeter / m;
  std::vector<double> u(static_cast<std::size_t>(m) + 1);
  u[0] = 0.0;
  for (int k = 1; k < m; ++k)
    u[static_cast<std::size_t>(k)] = ellipse_angle_at(a, b, u[static_cast<std::size_t>(k - 1)], ds);
  u[static_cast<std::size_t>(m)] = 2 * pi;
  for (int k = 0; k < m; ++k) {
    const double u0 = u[static_cast<std::size_t>(k)], u1 = u[static_cast<std::size_t>(k + 1)];
    const double length = ellipse_arc_length(a, b, u0, u1);
    const double um = ellipse_angle_at(a, b, u0, 0.5 * length);
    const Vec2d c = C(um);
    const Vec2d outward = Vec2d(b * std::cos(um), a * std::sin(um)).normalized();
    const Vec2d n = inside ? Vec2d(-outward) : outward;
    const Vec2d A = inside ? C(u0) : C(u1), B = inside ? C(u1) : C(u0);
    // Circle through A, c, B (signed: > 0 when the fluid is on its concave side).
    const Vec2d p = c - A, q = B - A;
    const double cr = p.x() * q.y() - p.y() * q.x();
    const double kappa_abs = 2.0 * std::abs(cr) / (p.norm() * q.norm() * (B - c).norm());
    const double kappa = inside ? kappa_abs : -kappa_abs;
    // How far the ellipse strays from that arc (the circle the integration uses: c + n/kappa).
    const Vec2d centre_of_arc = c + n / kappa;
    double g = 0;
    for (double f : {0.0, 0.125, 0.25, 0.375, 0.625, 0.75, 0.875, 1.0}) {
      const double uf = f == 0.0 ? u0 : (f == 1.0 ? u1 : ellipse_angle_at(a, b, u0, f * length));
      g = std::max(g, std::abs((C(uf) - centre_of_arc).norm() - 1.0 / kappa_abs));
    }
    out.add_curved_arc(A, B, c, n, length, kappa, 2.0 * g + 1e-14 * length);
  }
  return true;
}

// ---- 3-D walls -------------------------------------------------------------------------------

void add_rectangle(BoundaryElements<3>& out, const Vec3d& origin, const Vec3d& e1, const Vec3d& e2,
                   double dx, const Bounds<3>* keep = nullptr) {
  const BoundaryElements<3> r = rectangle_elements(origin, e1, e2, dx);
  if (!keep) {
    out.append(r);
    return;
  }
  const double tol = 1e-9 * keep->diagonal().norm();
  const Bounds<3> grown(keep->min().array() - tol, keep->max().array() + tol);
  for (std::size_t j = 0; j < r.size(); ++j)
    if (grown.contains(r.centre[j])) out.add_polygon(r.vertices[j].data(), r.vertex_count[j]);
}

bool plane_3d(const Wall<3>& w, double dx, const Bounds<3>& bounds, BoundaryElements<3>& out) {
  const auto* p = dynamic_cast<const PlaneWall<3>*>(&w);
  if (!p) return false;
  require_bounds(bounds, w.describe());
  const Vec3d n = p->normal(), o = p->point();
  const auto [t1, t2] = orthonormal_frame(n);
  // The plane's intersection with the box: where its 12 edges cross the plane.
  double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
  bool any = false;
  for (int i = 0; i < 8; ++i) {
    const Vec3d a = bounds.corner(static_cast<Bounds<3>::CornerType>(i));
    for (int axis = 0; axis < 3; ++axis) {
      if (i & (1 << axis)) continue;
      const Vec3d b = bounds.corner(static_cast<Bounds<3>::CornerType>(i | (1 << axis)));
      const double da = n.dot(a - o), db = n.dot(b - o);
      if ((da > 0 && db > 0) || (da < 0 && db < 0)) continue;
      const Vec3d x = da == db ? a : Vec3d(a + (b - a) * (da / (da - db)));
      const Vec3d r = x - o;
      u0 = std::min(u0, t1.dot(r));
      u1 = std::max(u1, t1.dot(r));
      v0 = std::min(v0, t2.dot(r));
      v1 = std::max(v1, t2.dot(r));
      any = true;
    }
  }
  if (!any || !(u1 > u0) || !(v1 > v0)) return true;
  add_rectangle(out, o + u0 * t1 + v0 * t2, (u1 - u0) * t1, (v1 - v0) * t2, dx, &bounds);
  return true;
}

bool box_3d(const Wall<3>& w, double dx, const Bounds<3>&, BoundaryElements<3>& out) {
  const auto* b = dynamic_cast<const BoxWall<3>*>(&w);
  if (!b) return false;
  const Vec3d lo = b->min(), L = b->max() - b->min();
  const bool inside = b->side() == FluidSide::inside;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const Vec3d ej = L[j] * Vec3d::Unit(j), ek = L[k] * Vec3d::Unit(k);
    // e_j x e_k = e_i: the min face looks along +e_i (into the box), the max face along -e_i.
    const Vec3d top = lo + L[i] * Vec3d::Unit(i);
    if (inside) {
      add_rectangle(out, lo, ej, ek, dx);
      add_rectangle(out, top, ek, ej, dx);
    } else {
      add_rectangle(out, lo, ek, ej, dx);
      add_rectangle(out, top, ej, ek, dx);
    }
  }
  return true;
}

bool cylinder_3d(const Wall<3>& w, double dx, const Bounds<3>& bounds, BoundaryElements<3>& out) {
  const auto* cy = dynamic_cast<const CylinderWall*>(&w);
  if (!cy) return false;
  require_bounds(bounds, w.describe());
  const Vec3d ax = cy->axis(), p = cy->point();
  Vec3d e1, e2;  // std::tie as in cylinder.cpp: clang 14 cannot capture a structured binding
  std::tie(e1, e2) = orthonormal_frame(ax);
  const double R = cy->radius(), s = cy->side() == FluidSide::inside ? -1.0 : 1.0;
  double v0 = std::numeric_limits<double>::infinity(), v1 = -v0;
  for (int i = 0; i < 8; ++i) {
    const double v = ax.dot(bounds.corner(static_cast<Bounds<3>::CornerType>(i)) - p);
    v0 = std::min(v0, v);
    v1 = std::max(v1, v);
  }
  const int mu = count_for(2 * pi * R, dx, 3), mv = count_for(v1 - v0, dx, 1);
  auto S = [&](double u, double v) {
    return Vec3d(p + v * ax + R * (std::cos(u) * e1 + std::sin(u) * e2));
  };
  auto N = [&](double u, double) { return Vec3d(s * (std::cos(u) * e1 + std::sin(u) * e2)); };
  const double du = 2 * pi / mu, dv = (v1 - v0) / mv;
  for (int i = 0; i < mu; ++i)
    for (int k = 0; k < mv; ++k)
      add_surface_cell(out, S, N, i * du, (i + 1) * du, v0 + k * dv, v0 + (k + 1) * dv,
                       R * du * dv);
  return true;
}

bool sphere_3d(const Wall<3>& w, double dx, const Bounds<3>&, BoundaryElements<3>& out) {
  const auto* sp = dynamic_cast<const SphereWall*>(&w);
  if (!sp) return false;
  const Vec3d c = sp->center();
  const double R = sp->radius(), s = sp->side() == FluidSide::inside ? -1.0 : 1.0;
  auto radial = [](double t, double f) {
    return Vec3d(std::sin(t) * std::cos(f), std::sin(t) * std::sin(f), std::cos(t));
  };
  auto S = [&](double t, double f) { return Vec3d(c + R * radial(t, f)); };
  auto N = [&](double t, double f) { return Vec3d(s * radial(t, f)); };
  // One azimuthal count for every band: no T-junctions (see the header).
  const int mt = count_for(pi * R, dx, 2), mf = count_for(2 * pi * R, dx, 3);
  const double dt = pi / mt, df = 2 * pi / mf;
  for (int i = 0; i < mt; ++i) {
    const double t0 = i * dt, t1 = (i + 1) * dt;
    for (int k = 0; k < mf; ++k)
      add_surface_cell(out, S, N, t0, t1, k * df, (k + 1) * df,
                       R * R * (std::cos(t0) - std::cos(t1)) * df);
  }
  return true;
}

bool torus_3d(const Wall<3>& w, double dx, const Bounds<3>&, BoundaryElements<3>& out) {
  const auto* to = dynamic_cast<const TorusWall*>(&w);
  if (!to) return false;
  const Vec3d c = to->center(), ax = to->axis();
  Vec3d e1, e2;
  std::tie(e1, e2) = orthonormal_frame(ax);
  const double R = to->major_radius(), a = to->minor_radius();
  const double s = to->side() == FluidSide::inside ? -1.0 : 1.0;
  auto outward = [&](double t, double f) {
    const Vec3d rho = std::cos(f) * e1 + std::sin(f) * e2;
    return Vec3d(std::cos(t) * rho + std::sin(t) * ax);
  };
  auto S = [&](double t, double f) {
    const Vec3d rho = std::cos(f) * e1 + std::sin(f) * e2;
    return Vec3d(c + R * rho + a * outward(t, f));
  };
  auto N = [&](double t, double f) { return Vec3d(s * outward(t, f)); };
  const int mt = count_for(2 * pi * a, dx, 3), mf = count_for(2 * pi * R, dx, 3);
  const double dt = 2 * pi / mt, df = 2 * pi / mf;
  for (int i = 0; i < mt; ++i) {
    const double t0 = -pi + i * dt, t1 = -pi + (i + 1) * dt;
    const double area = a * df * (R * dt + a * (std::sin(t1) - std::sin(t0)));
    for (int k = 0; k < mf; ++k) add_surface_cell(out, S, N, t0, t1, k * df, (k + 1) * df, area);
  }
  return true;
}

// ---- The one table of wall types -------------------------------------------------------------

template <int D>
using Discretizer = bool (*)(const Wall<D>&, double, const Bounds<D>&, BoundaryElements<D>&);

template <int D>
const std::vector<Discretizer<D>>& discretizers();

template <>
const std::vector<Discretizer<2>>& discretizers<2>() {
  // A new 2-D wall type: one function like those above, one line here.
  static const std::vector<Discretizer<2>> table = {plane_2d, box_2d, circle_2d, ellipse_2d,
                                                    wall_elements_detail::nurbs_curve_2d};
  return table;
}

template <>
const std::vector<Discretizer<3>>& discretizers<3>() {
  // A new 3-D wall type: one function like those above, one line here.
  static const std::vector<Discretizer<3>> table = {plane_3d,
                                                    box_3d,
                                                    cylinder_3d,
                                                    sphere_3d,
                                                    torus_3d,
                                                    wall_elements_detail::nurbs_surface_3d,
                                                    wall_elements_detail::trimmed_face_3d,
                                                    wall_elements_detail::cad_solid_3d,
                                                    wall_elements_detail::trimesh_3d};
  return table;
}

}  // namespace

double ellipse_arc_length(double a, double b, double u0, double u1) {
  const double sign = u1 >= u0 ? 1.0 : -1.0;
  if (u1 < u0) std::swap(u0, u1);
  const int pieces = std::max(1, static_cast<int>(std::ceil((u1 - u0) * 16.0)));
  return sign *
         gauss_legendre_8([&](double u) { return std::hypot(a * std::sin(u), b * std::cos(u)); },
                          u0, u1, pieces);
}

template <int D>
BoundaryElements<D> elements_from_wall(const Wall<D>& wall, double dx, const Bounds<D>& bounds) {
  if (!(dx > 0)) throw std::invalid_argument("boundary elements: dx must be > 0");
  BoundaryElements<D> out;
  // A moving wall: its body's elements, placed where the wall is now (rigidly: areas,
  // curvatures and gaps are invariant).
  if (const auto* mw = dynamic_cast<const MovingWall<D>*>(&wall)) {
    out = elements_from_wall<D>(mw->body(), dx, bounds);
    for (std::size_t b = 0; b < out.size(); ++b) {
      out.centre[b] = mw->to_world(out.centre[b]);
      out.normal[b] = mw->rotation() * out.normal[b];
      for (int v = 0; v < out.vertex_count[b]; ++v)
        out.vertices[b][static_cast<std::size_t>(v)] =
            mw->to_world(out.vertices[b][static_cast<std::size_t>(v)]);
    }
    return out;
  }
  for (const Discretizer<D> f : discretizers<D>())
    if (f(wall, dx, bounds, out)) return out;
  throw std::invalid_argument("no boundary-element generator for the wall '" + wall.describe() +
                              "'");
}

template <int D>
BoundaryElements<D> elements_from_walls(const WallSet<D>& walls, double dx,
                                        const Bounds<D>& bounds) {
  BoundaryElements<D> out;
  for (const auto& w : walls.walls()) out.append(elements_from_wall<D>(*w, dx, bounds));
  return out;
}

template BoundaryElements<2> elements_from_wall<2>(const Wall<2>&, double, const Bounds<2>&);
template BoundaryElements<3> elements_from_wall<3>(const Wall<3>&, double, const Bounds<3>&);
template BoundaryElements<2> elements_from_walls<2>(const WallSet<2>&, double, const Bounds<2>&);
template BoundaryElements<3> elements_from_walls<3>(const WallSet<3>&, double, const Bounds<3>&);

}  // namespace curvsph
