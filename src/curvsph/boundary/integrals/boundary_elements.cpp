#include "curvsph/boundary/integrals/boundary_elements.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace curvsph {

template <int D>
void BoundaryElements<D>::reserve(std::size_t n) {
  centre.reserve(n);
  normal.reserve(n);
  area.reserve(n);
  vertices.reserve(n);
  vertex_count.reserve(n);
  curvature.reserve(n);
  gap.reserve(n);
}

template <int D>
void BoundaryElements<D>::append(const BoundaryElements& o) {
  centre.insert(centre.end(), o.centre.begin(), o.centre.end());
  normal.insert(normal.end(), o.normal.begin(), o.normal.end());
  area.insert(area.end(), o.area.begin(), o.area.end());
  vertices.insert(vertices.end(), o.vertices.begin(), o.vertices.end());
  vertex_count.insert(vertex_count.end(), o.vertex_count.begin(), o.vertex_count.end());
  curvature.insert(curvature.end(), o.curvature.begin(), o.curvature.end());
  gap.insert(gap.end(), o.gap.begin(), o.gap.end());
}

// The dimension-specific members are explicit specializations, not constrained members of the
// template: clang 14 (clang-tidy) instantiates constrained members in the explicit
// instantiations below even where the constraint fails.
template <>
void BoundaryElements<2>::add_segment(const VecD<2>& a, const VecD<2>& b) {
  add_arc(a, b, 0.0);
}

template <>
void BoundaryElements<2>::add_arc(const VecD<2>& a, const VecD<2>& b, double kappa) {
  const VecD<2> chord = b - a;
  const double c = chord.norm();
  if (!(c > 0)) throw std::invalid_argument("boundary element with zero length");
  const VecD<2> t = chord / c;
  const VecD<2> n(-t[1], t[0]);  // fluid on the left of a -> b
  VecD<2> mid = 0.5 * (a + b);
  double length = c;
  if (kappa != 0.0) {
    const double R = 1.0 / std::abs(kappa);
    if (c > 2.0 * R) throw std::invalid_argument("arc chord longer than the circle's diameter");
    const double half = std::asin(0.5 * c / R);  // half the opening angle (minor arc)
    length = 2.0 * half * R;
    // The arc bulges away from the fluid when kappa > 0 (concave seen from the fluid).
    const double sagitta = R * (1.0 - std::cos(half));
    mid -= (kappa > 0 ? 1.0 : -1.0) * sagitta * n;
  }
  centre.push_back(mid);
  normal.push_back(n);
  area.push_back(length);
  vertices.push_back({a, b});
  vertex_count.push_back(2);
  curvature.push_back(kappa);
  gap.push_back(0.0);
}

template <>
void BoundaryElements<3>::add_polygon(const VecD<3>* v, int count) {
  if (count < 3 || count > 4) throw std::invalid_argument("3-D elements have 3 or 4 vertices");
  VecD<3> cross = VecD<3>::Zero();
  VecD<3> mean = VecD<3>::Zero();
  for (int k = 1; k + 1 < count; ++k) cross += (v[k] - v[0]).cross(v[k + 1] - v[0]);
  const double twice_area = cross.norm();
  if (!(twice_area > 0)) throw std::invalid_argument("boundary element with zero area");
  // Area-weighted centroid of the fan triangles.
  for (int k = 1; k + 1 < count; ++k) {
    const double w = (v[k] - v[0]).cross(v[k + 1] - v[0]).norm();
    mean += w * (v[0] + v[k] + v[k + 1]) / 3.0;
  }
  Vertices verts;
  verts.fill(VecD<3>::Zero());
  for (int k = 0; k < count; ++k) verts[static_cast<std::size_t>(k)] = v[k];
  centre.push_back(mean / twice_area);
  normal.push_back(cross / twice_area);
  area.push_back(0.5 * twice_area);
  vertices.push_back(verts);
  vertex_count.push_back(count);
  curvature.push_back(0.0);
  gap.push_back(0.0);
}

template <>
void BoundaryElements<2>::add_curved_arc(const VecD<2>& a, const VecD<2>& b, const VecD<2>& c,
                                         const VecD<2>& n, double length, double kappa, double g) {
  if (!((b - a).norm() > 0) || !(length > 0))
    throw std::invalid_argument("boundary element with zero length");
  if (kappa != 0.0 && (b - a).norm() > 2.0 / std::abs(kappa))
    throw std::invalid_argument("arc chord longer than the circle's diameter");
  centre.push_back(c);
  normal.push_back(n.normalized());
  area.push_back(length);
  vertices.push_back({a, b});
  vertex_count.push_back(2);
  curvature.push_back(kappa);
  gap.push_back(std::max(0.0, g));
}

template <>
void BoundaryElements<3>::add_curved_patch(const VecD<3>* v, int count, const VecD<3>& c,
                                           const VecD<3>& n, double a, double g) {
  if (count < 3 || count > 4) throw std::invalid_argument("3-D elements have 3 or 4 vertices");
  if (!(a > 0)) throw std::invalid_argument("boundary element with zero area");
  Vertices verts;
  verts.fill(VecD<3>::Zero());
  for (int k = 0; k < count; ++k) verts[static_cast<std::size_t>(k)] = v[k];
  centre.push_back(c);
  normal.push_back(n.normalized());
  area.push_back(a);
  vertices.push_back(verts);
  vertex_count.push_back(count);
  curvature.push_back(0.0);
  gap.push_back(std::max(0.0, g));
}

template <int D>
double BoundaryElements<D>::bounding_radius(std::size_t j) const {
  double r = 0;
  for (int k = 0; k < vertex_count[j]; ++k)
    r = std::max(r, (vertices[j][static_cast<std::size_t>(k)] - centre[j]).norm());
  return r;  // minor arcs lie within the ball through their end points about their midpoint
}

template struct BoundaryElements<2>;
template struct BoundaryElements<3>;

BoundaryElements<2> polyline_elements(const std::vector<Vec2d>& points, double dx, bool closed) {
  if (!(dx > 0)) throw std::invalid_argument("polyline_elements: dx must be > 0");
  BoundaryElements<2> out;
  const std::size_t n = points.size();
  const std::size_t sides = closed ? n : (n == 0 ? 0 : n - 1);
  for (std::size_t s = 0; s < sides; ++s) {
    const Vec2d a = points[s], b = points[(s + 1) % n];
    const int m = std::max(1, static_cast<int>(std::lround((b - a).norm() / dx)));
    for (int k = 0; k < m; ++k)
      out.add_segment(a + (b - a) * (double(k) / m), a + (b - a) * (double(k + 1) / m));
  }
  return out;
}

BoundaryElements<2> circle_elements(const Vec2d& c, double radius, double dx, bool fluid_inside,
                                    double start_angle) {
  if (!(dx > 0) || !(radius > 0)) throw std::invalid_argument("circle_elements: bad dx/radius");
  const int m = std::max(3, static_cast<int>(std::lround(2 * std::numbers::pi * radius / dx)));
  BoundaryElements<2> out;
  out.reserve(static_cast<std::size_t>(m));
  auto point = [&](int k) {
    const double phi = start_angle + 2 * std::numbers::pi * k / m;
    return Vec2d(c[0] + radius * std::cos(phi), c[1] + radius * std::sin(phi));
  };
  for (int k = 0; k < m; ++k) {
    // Counter-clockwise keeps the inside on the left; clockwise the outside.
    if (fluid_inside) {
      out.add_arc(point(k), point(k + 1), 1.0 / radius);
    } else {
      out.add_arc(point(m - k), point(m - k - 1), -1.0 / radius);
    }
  }
  return out;
}

BoundaryElements<3> rectangle_elements(const Vec3d& origin, const Vec3d& e1, const Vec3d& e2,
                                       double dx) {
  if (!(dx > 0)) throw std::invalid_argument("rectangle_elements: dx must be > 0");
  const int m1 = std::max(1, static_cast<int>(std::lround(e1.norm() / dx)));
  const int m2 = std::max(1, static_cast<int>(std::lround(e2.norm() / dx)));
  BoundaryElements<3> out;
  out.reserve(static_cast<std::size_t>(m1) * m2);
  for (int i = 0; i < m1; ++i) {
    for (int j = 0; j < m2; ++j) {
      auto p = [&](int a, int b) {
        return Vec3d(origin + e1 * (double(a) / m1) + e2 * (double(b) / m2));
      };
      const Vec3d v[4] = {p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)};
      out.add_polygon(v, 4);
    }
  }
  return out;
}

BoundaryElements<3> triangle_elements(const std::vector<std::array<Vec3d, 3>>& triangles) {
  BoundaryElements<3> out;
  out.reserve(triangles.size());
  for (const auto& t : triangles) out.add_polygon(t.data(), 3);
  return out;
}

}  // namespace curvsph
