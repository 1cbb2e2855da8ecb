#pragma once
// Internal to the Shepard factor (shepard.cpp, geometric_shepard.cpp): the element geometry
// (distances, on-wall tests), the Gauss rules and the element-by-element geometric factor
// that the reference quadrature (shepard_geometric) and the solver's GeometricShepard share.
// Not part of the public interface (shepard.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "curvsph/boundary/integrals/boundary_elements.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/kernels/boundary_kernel.hpp"

namespace curvsph::shepard_detail {

constexpr double pi = std::numbers::pi;

// Gauss-Legendre rule on [0, 1] with n points (Newton on P_n), cached per n (n <= 32).
struct GaussRule {
  std::vector<double> x, w;
};
const GaussRule& gauss_rule(int n);

inline double cross2(const Vec2d& a, const Vec2d& b) {
  return a[0] * b[1] - a[1] * b[0];
}

// Arc geometry of a 2-D element with curvature kappa != 0: circle centre O.
inline Vec2d arc_circle_centre(const BoundaryElements<2>& el, std::size_t j) {
  return el.centre[j] + el.normal[j] / el.curvature[j];  // c - O = -n / kappa
}

// The element geometry below is defined in shepard.cpp, out of line on purpose: inlined into
// geometric_impl's per-element loop (where the bounding-ball test skips it for most elements)
// it made GeometricShepard<3> 6 % more instructions (callgrind, BM_PhaseBoundaryIntegralsPrepass).

// Whether p's projection on element j's plane lies inside the polygon (tol: outward margin).
bool point_in_polygon(const BoundaryElements<3>& el, std::size_t j, const Vec3d& p, double tol);
double segment_distance(const Vec3d& a, const Vec3d& b, const Vec3d& x);

// Distance from x to element j (exact for segments, arcs and planar polygons).
double element_distance(const BoundaryElements<2>& el, std::size_t j, const Vec2d& x);
double element_distance(const BoundaryElements<3>& el, std::size_t j, const Vec3d& x);

// Signed offset of x from element j's integrated shape (> 0 on the fluid side) and whether
// x projects onto the element (for the `gap` band of curved-wall elements).
double signed_offset(const BoundaryElements<2>& el, std::size_t j, const Vec2d& x, bool& onto);
double signed_offset(const BoundaryElements<3>& el, std::size_t j, const Vec3d& x, bool& onto);

// Polynomial part int_j n(y).(y - x) F_Pext(|y - x|) dy of element j (Gauss points; shepard.cpp).
double poly_part(const BoundaryElements<2>& el, std::size_t j, const Vec2d& x,
                 const BoundaryKernel<2>& F, const ShepardQuadrature& q);
double poly_part(const BoundaryElements<3>& el, std::size_t j, const Vec3d& x,
                 const BoundaryKernel<3>& F, const ShepardQuadrature& q);

template <int D>
constexpr double sphere_measure() {
  return D == 2 ? 2 * pi : 4 * pi;
}

// The geometric factor over the elements `for_each(fn)` visits (all, or a candidate list).
// Singular and polynomial parts element by element (shepard_geometric's quadrature).
template <int D>
double element_parts(const BoundaryElements<D>& el, std::span<const std::size_t> near,
                     const VecD<D>& x, const VecD<D>& xs, const BoundaryKernel<D>& F,
                     const ShepardQuadrature& quad) {
  double angles = 0, poly = 0;
  for (std::size_t j : near) {
    angles += subtended_angle<D>(el, j, xs);
    poly += poly_part(el, j, x, F, quad);
  }
  return angles / sphere_measure<D>() + poly;
}

// `skip_far`: leave out elements whose exact distance is >= 2h (GeometricShepard);
// `parts_of(near, x, xs)`: the sum over the elements `near` of the singular part (angle /
// solid angle over the sphere's measure, seen from xs) and the polynomial part (at x).
// `radius`: el.bounding_radius(j) for every j, tabulated (GeometricShepard), or null;
// `reach`: with it, a bound on d(x, element j) - |x - centre_j| (about 0 where the centre
// lies on the element, else the bounding radius), or null for the bounding radius.
template <int D, class ForEach, class Parts>
double geometric_impl(const BoundaryElements<D>& el, const VecD<D>& x, double h,
                      const ShepardQuadrature& quad, const ForEach& for_each, bool skip_far,
                      const Parts& poly_of, const double* radius = nullptr,
                      const double* reach = nullptr) {
  const double support = 2.0 * h;
  const double tol = quad.on_wall_tolerance * h;
  // Candidates: elements reaching into the support ball; the rest contribute exactly 0.
  // Thread-local scratch: the solver calls this for every particle near a wall, every step.
  thread_local std::vector<std::size_t> near, touched;
  near.clear();
  touched.clear();
  VecD<D> mean_normal = VecD<D>::Zero();
  double behind = 0.0;  // how far x lies behind curved-wall elements within their gap
  // Far from touching: the element lies in the ball of its bounding radius rb about its
  // centre, so its distance d is in [rc - rb, rc + rb] (at most rc where the centre lies on
  // the element: flat polygons); when that interval is clear of the
  // on-wall band (tol, or gap + tol) and, with skip_far, inside the support, no decision
  // below depends on d and the exact distance is not computed (most elements of a particle
  // one or more rows from the wall). The margins cover the round-off of rc - rb and rc + rb.
  const double margin = 1e-12 * support;
  for_each([&](std::size_t j) {
    const double rc = (el.centre[j] - x).norm();
    const double rb = radius ? radius[j] : el.bounding_radius(j);
    if (rc - rb >= support) return;
    const double band = tol + (j < el.gap.size() ? std::max(el.gap[j], 0.0) : 0.0);
    const double ub = rc + (reach ? reach[j] : rb);
    if (rc - rb > band + margin && (!skip_far || ub < support - margin)) {
      near.push_back(j);
      return;
    }
    const double d = element_distance(el, j, x);
    if (skip_far && d >= support) return;
    near.push_back(j);
    bool hit = d <= tol;
    if (!hit && j < el.gap.size() && el.gap[j] > 0.0 && d <= el.gap[j] + tol) {
      // Between the element and the curved wall it stands for: on the wall.
      bool onto = false;
      const double s = signed_offset(el, j, x, onto);
      if (onto && s < 0.0) {
        hit = true;
        behind = std::max(behind, -s);
      }
    }
    if (hit) touched.push_back(j);
  });
  // On the wall: the singular part is the limit from the fluid side along the mean normal of
  // the touched elements (makes contact points, vertices and corner apexes exact); a point
  // behind a curved-wall element by less than its gap is first moved to its fluid side.
  // The mean normal is taken over the faces touched, each face once: every touched element
  // counts 1 / (the number of touched elements with a normal within 11 degrees of its own).
  // A plain mean over elements leans towards the face with more elements at x (a point on an
  // edge at a vertex of one face's grid and inside an element of the other): where faces meet
  // at 60 degrees, two elements of one and one of the other put the mean normal in the plane
  // of the one, and xs left the fluid through it (gamma off by 1: a NURBS floor meeting a
  // wall, tests/boundary/test_wall_elements_nurbs.cpp). For the same reason an element that
  // the move from x to xs could cross (within the move's length of x) is counted as touched
  // too, and the move recomputed.
  VecD<D> xs = x;
  for (int pass = 0; pass < 4 && !touched.empty(); ++pass) {
    mean_normal = VecD<D>::Zero();
    for (std::size_t j : touched) {
      int alike = 0;
      for (std::size_t k : touched) alike += el.normal[k].dot(el.normal[j]) > 0.98 ? 1 : 0;
      mean_normal += el.normal[j] / alike;
    }
    const double mn = mean_normal.norm();
    if (!(mn > 1e-12)) break;
    const VecD<D> m = mean_normal / mn;
    double cmin = 1.0;
    for (std::size_t j : touched) cmin = std::min(cmin, el.normal[j].dot(m));
    const double move = 1.5 * behind / std::max(cmin, 0.2) + 1e-9 * h;
    xs = x + move * m;
    if (behind == 0.0) break;  // a move of 1e-9 h: every element that close is touched
    bool more = false;
    for (std::size_t j : near)
      if (std::find(touched.begin(), touched.end(), j) == touched.end() &&
          element_distance(el, j, x) <= move + tol) {
        touched.push_back(j);
        more = true;
      }
    if (!more) break;
  }
  return 1.0 - poly_of(std::span<const std::size_t>(near), x, xs);
}

}  // namespace curvsph::shepard_detail
