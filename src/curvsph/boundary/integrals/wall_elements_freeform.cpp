// Boundary elements of the free-form walls (wall_elements.hpp lists what each gives): NURBS
// curves (2-D), NURBS surfaces and triangle meshes (3-D).
#include "curvsph/boundary/integrals/wall_elements_freeform.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "curvsph/core/quadrature.hpp"
#include "curvsph/geometry/nurbs_curve_wall.hpp"
#include "curvsph/geometry/nurbs_surface_wall.hpp"
#include "curvsph/geometry/trimesh_wall.hpp"
#include "curvsph/nurbs/sampling.hpp"

namespace curvsph::wall_elements_detail {

namespace {

// Parameters where a B-spline of degree p may have a corner: the interior knots of
// multiplicity >= p (continuity C^(p - multiplicity) <= C^0; Piegl & Tiller §2.3), plus the
// ends. Elements never straddle them, so a polyline of degree 1 gives exact segments and a
// kinked curve exact corners.
std::vector<double> crease_breaks(const std::vector<double>& U, int p, double t0, double t1) {
  std::vector<double> out{t0};
  for (std::size_t k = 0; k < U.size();) {
    std::size_t e = k;
    while (e < U.size() && U[e] == U[k]) ++e;
    if (U[k] > t0 && U[k] < t1 && static_cast<int>(e - k) >= p) out.push_back(U[k]);
    k = e;
  }
  out.push_back(t1);
  return out;
}

// Parameter t in [lo, hi] with arc length s from lo (Newton on ds/dt = |C'|, bracketed by
// bisection as in nurbs::sample_arc_length).
double param_at_length(const nurbs::NurbsCurve<2>& c, double lo, double hi, double s) {
  const double t_lo = lo, total = nurbs::arc_length(c, lo, hi);
  double t = lo + (hi - lo) * std::clamp(s / total, 0.0, 1.0);
  for (int it = 0; it < 60; ++it) {
    const double f = nurbs::arc_length(c, t_lo, t) - s;
    if (std::abs(f) <= 1e-13 * total) break;
    (f > 0 ? hi : lo) = t;
    const double speed = c.eval(t).d1.norm();
    const double t_new = speed > 0 ? t - f / speed : 0.5 * (lo + hi);
    t = (t_new > lo && t_new < hi) ? t_new : 0.5 * (lo + hi);
  }
  return t;
}

double cross2(const Vec2d& a, const Vec2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The element of curve c over [t0, t1] (no crease inside): vertices C(t0), C(t1), centre at
// half the arc length, normal of the curve there, length = the arc length; integrated as the
// circular arc through the three points (as the ellipse's elements), or as the chord where the
// piece is straight. gap = twice the curve's largest distance from that arc or chord.
void add_curve_element(BoundaryElements<2>& out, const nurbs::NurbsCurve<2>& c, bool left,
                       double t0, double t1) {
  const double length = nurbs::arc_length(c, t0, t1);
  const double tm = param_at_length(c, t0, t1, 0.5 * length);
  const nurbs::CurveDerivs<2> dm = c.eval(tm);
  const Vec2d centre = dm.c;
  const Vec2d nl = Vec2d(-dm.d1.y(), dm.d1.x()).normalized();  // left of increasing t
  const Vec2d n = left ? nl : Vec2d(-nl);
  // Fluid on the left of a -> b (BoundaryElements' convention).
  const Vec2d a = left ? c.point(t0) : c.point(t1), b = left ? c.point(t1) : c.point(t0);
  const Vec2d p = centre - a, q = b - a;
  const double cr = cross2(p, q);
  constexpr std::array<double, 7> fractions = {0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875};
  if (std::abs(cr) <= 1e-12 * p.norm() * q.norm()) {
    // The centre on the chord: straight (always for degree 1), or an inflection.
    const Vec2d e = q.normalized(), en(-e.y(), e.x());
    double g = 0;
    for (double f : fractions) g = std::max(g, std::abs(en.dot(c.point(t0 + f * (t1 - t0)) - a)));
    if (g <= 1e-12 * length) {
      out.add_segment(a, b);
    } else {
      out.add_curved_arc(a, b, centre, n, length, 0.0, 2.0 * g);
    }
    return;
  }
  // Circle through a, centre, b: cr > 0 when the centre lies right of a -> b, i.e. the arc
  // bulges away from the fluid (concave seen from it: kappa > 0, DESIGN sign).
  const double kappa_abs = 2.0 * std::abs(cr) / (p.norm() * q.norm() * (b - centre).norm());
  const double kappa = cr > 0 ? kappa_abs : -kappa_abs;
  const Vec2d O = centre + n / kappa;
  double g = 0;
  for (double f : fractions)
    g = std::max(g, std::abs((c.point(t0 + f * (t1 - t0)) - O).norm() - 1.0 / kappa_abs));
  out.add_curved_arc(a, b, centre, n, length, kappa, 2.0 * g + 1e-14 * length);
}

// Grid lines of one parameter direction: those of nurbs::sample_surface (equal chord length
// of iso-curves, about dx apart), with every crease knot made a grid line (the nearest
// ordinary line within 0.4 of a cell is dropped for it).
std::vector<double> grid_with_creases(std::vector<double> grid,
                                      const std::vector<double>& creases) {
  std::vector<double> out;
  const std::size_t n = grid.size();
  for (std::size_t i = 0; i < n; ++i) {
    const bool end = i == 0 || i + 1 == n;
    bool near = false;
    for (std::size_t k = 1; k + 1 < creases.size() && !end; ++k) {
      const double cell = 0.5 * (grid[std::min(i + 1, n - 1)] - grid[i > 0 ? i - 1 : 0]);
      near = near || std::abs(grid[i] - creases[k]) < 0.4 * cell;
    }
    if (!near) out.push_back(grid[i]);
  }
  for (std::size_t k = 1; k + 1 < creases.size(); ++k) out.push_back(creases[k]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// int over [a, b] x [c, d] of |S_u x S_v| (Gauss-Legendre 8 x 8 on the sub-rectangles between
// knots, where the integrand is smooth): the exact area of the curved cell to round-off.
double cell_area(const nurbs::NurbsSurface& s, double a, double b, double c, double d) {
  auto cuts = [](const std::vector<double>& U, double lo, double hi) {
    std::vector<double> out{lo};
    for (double u : U)
      if (u > lo && u < hi && u != out.back()) out.push_back(u);
    out.push_back(hi);
    return out;
  };
  const std::vector<double> cu = cuts(s.knots_u(), a, b), cv = cuts(s.knots_v(), c, d);
  double area = 0;
  for (std::size_t i = 0; i + 1 < cu.size(); ++i)
    for (std::size_t k = 0; k + 1 < cv.size(); ++k)
      area += gauss_legendre_8(
          [&](double u) {
            return gauss_legendre_8(
                [&](double v) {
                  const nurbs::SurfaceDerivs e = s.eval(u, v);
                  return e.su.cross(e.sv).norm();
                },
                cv[k], cv[k + 1]);
          },
          cu[i], cu[i + 1]);
  return area;
}

}  // namespace

bool nurbs_curve_2d(const Wall<2>& w, double dx, const Bounds<2>&, BoundaryElements<2>& out) {
  const auto* wall = dynamic_cast<const NurbsCurveWall*>(&w);
  if (!wall) return false;
  const nurbs::NurbsCurve<2>& c = wall->curve();
  const bool left = wall->fluid() == NurbsCurveWall::Side::left;
  const std::vector<double> breaks = crease_breaks(c.knots(), c.degree(), c.t0(), c.t1());
  const bool one_closed_piece = c.closed() && breaks.size() == 2;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double ta = breaks[k], tb = breaks[k + 1];
    const double L = nurbs::arc_length(c, ta, tb);
    if (!(L > 0)) continue;  // a piece collapsed to a point
    const int m = std::max(one_closed_piece ? 3 : 1, static_cast<int>(std::lround(L / dx)));
    double t_prev = ta;
    for (int e = 1; e <= m; ++e) {
      const double t = e == m ? tb : param_at_length(c, ta, tb, L * e / m);
      add_curve_element(out, c, left, t_prev, t);
      t_prev = t;
    }
  }
  return true;
}

bool nurbs_surface_3d(const Wall<3>& w, double dx, const Bounds<3>&, BoundaryElements<3>& out) {
  const auto* wall = dynamic_cast<const NurbsSurfaceWall*>(&w);
  if (!wall) return false;
  const nurbs::NurbsSurface& s = wall->surface();
  const double sign = wall->fluid() == NurbsSurfaceWall::Side::front ? 1.0 : -1.0;
  // The tensor grid of sample_surface (u rows, v fastest), split into its u and v lines.
  const nurbs::SurfaceSamples grid = nurbs::sample_surface(s, dx);
  std::size_t nv = 0;
  while (nv < grid.params.size() && grid.params[nv][0] == grid.params[0][0]) ++nv;
  std::vector<double> us, vs;
  for (std::size_t i = 0; i < grid.params.size(); i += nv) us.push_back(grid.params[i][0]);
  for (std::size_t j = 0; j < nv; ++j) vs.push_back(grid.params[j][1]);
  us = grid_with_creases(us, crease_breaks(s.knots_u(), s.degree_u(), s.u0(), s.u1()));
  vs = grid_with_creases(vs, crease_breaks(s.knots_v(), s.degree_v(), s.v0(), s.v1()));
  auto S = [&](double u, double v) { return s.point(u, v); };
  auto N = [&](double u, double v) {
    const nurbs::SurfaceDerivs e = s.eval(u, v);
    return Vec3d(sign * e.su.cross(e.sv).normalized());
  };
  for (std::size_t i = 0; i + 1 < us.size(); ++i)
    for (std::size_t k = 0; k + 1 < vs.size(); ++k) {
      const double area = cell_area(s, us[i], us[i + 1], vs[k], vs[k + 1]);
      if (area > 0) add_surface_cell(out, S, N, us[i], us[i + 1], vs[k], vs[k + 1], area);
    }
  return true;
}

bool trimesh_3d(const Wall<3>& w, double dx, const Bounds<3>&, BoundaryElements<3>& out) {
  const auto* mesh = dynamic_cast<const TriMeshWall*>(&w);
  if (!mesh) return false;
  const std::vector<Vec3d>& v = mesh->vertices();
  const std::vector<std::array<int, 3>>& tris = mesh->triangles();
  // The fluid side from the wall itself: its normal (into the fluid) at the centroid of the
  // largest triangle, against that triangle's (b - a) x (c - a).
  std::size_t big = 0;
  double big_area = 0;
  auto cross_of = [&](const std::array<int, 3>& t) {
    return Vec3d((v[static_cast<std::size_t>(t[1])] - v[static_cast<std::size_t>(t[0])])
                     .cross(v[static_cast<std::size_t>(t[2])] - v[static_cast<std::size_t>(t[0])]));
  };
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const double a = cross_of(tris[t]).norm();
    if (a > big_area) big_area = a, big = t;
  }
  if (!(big_area > 0)) return true;  // no triangle with an area
  const auto& T = tris[big];
  const Vec3d centroid = (v[static_cast<std::size_t>(T[0])] + v[static_cast<std::size_t>(T[1])] +
                          v[static_cast<std::size_t>(T[2])]) /
                         3.0;
  const bool flip = mesh->closest(centroid).normal.dot(cross_of(T)) < 0;
  // Each triangle as k^2 similar triangles (edges split in k), k from its area (pieces of
  // about dx^2 / 2, half a dx square: a right isosceles triangle gets legs of dx) or from its
  // longest edge (pieces no longer than about 2 dx), whichever is finer. Neighbours with
  // another k meet at T-junctions along their common straight edge: the elements still cover
  // the mesh exactly (no gap, no overlap), which is what the solid angles and the Shepard
  // factor need.
  for (const auto& t : tris) {
    Vec3d p0 = v[static_cast<std::size_t>(t[0])], p1 = v[static_cast<std::size_t>(t[1])],
          p2 = v[static_cast<std::size_t>(t[2])];
    if (flip) std::swap(p1, p2);
    if (!((p1 - p0).cross(p2 - p0).norm() > 0)) continue;  // degenerate triangle: no area
    const double longest = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm()});
    const double twice_area = (p1 - p0).cross(p2 - p0).norm();
    const int k = std::max(
        1, static_cast<int>(std::lround(std::max(std::sqrt(twice_area), 0.5 * longest) / dx)));
    auto at = [&](int i, int j) {  // lattice point i steps along p0->p1, j along p0->p2
      return Vec3d(p0 + (p1 - p0) * (double(i) / k) + (p2 - p0) * (double(j) / k));
    };
    for (int i = 0; i < k; ++i)
      for (int j = 0; i + j < k; ++j) {
        const Vec3d up[3] = {at(i, j), at(i + 1, j), at(i, j + 1)};
        out.add_polygon(up, 3);
        if (i + j + 1 < k) {
          const Vec3d down[3] = {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
          out.add_polygon(down, 3);
        }
      }
  }
  return true;
}

}  // namespace curvsph::wall_elements_detail
