#pragma once
// Boundary elements for boundary integrals (DESIGN.md §4), structure of arrays.
// Each element: centre, unit normal pointing INTO the fluid, area (length in 2-D) and its
// vertices, so that the angle (2-D) or solid angle (3-D) it subtends can be computed exactly.
//  - 2-D: a segment a -> b with the fluid on its left (normal = tangent rotated +90 deg), or
//    a circular arc through a and b (curvature != 0, DESIGN sign: > 0 when concave seen from
//    the fluid); the centre lies on the arc, the normal is the one at the centre and the
//    area is the arc length.
//  - 3-D: a planar convex polygon with 3 or 4 vertices ordered counter-clockwise seen from the
//    fluid, i.e. (v1 - v0) x (v2 - v0) along the normal.
// Generators for simple geometries are free functions below (the lead connects them to the
// general Wall types).
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

#include "curvsph/core/types.hpp"

namespace curvsph {

template <int D>
struct BoundaryElements {
  static_assert(D == 2 || D == 3);
  static constexpr int max_vertices = D == 2 ? 2 : 4;
  using Vertices = std::array<VecD<D>, max_vertices>;

  std::vector<VecD<D>> centre;
  std::vector<VecD<D>> normal;  // unit, into the fluid
  std::vector<double> area;     // length in 2-D
  std::vector<Vertices> vertices;
  std::vector<std::int32_t> vertex_count;  // 2 in 2-D; 3 or 4 in 3-D
  std::vector<double> curvature;           // 2-D arcs (signed, DESIGN sign); 0 = flat
  // How far the true wall may lie from the element's integrated shape (the arc or the planar
  // polygon): 0 for exact elements (segments, circle arcs, flat patches); > 0 for elements
  // that stand for a piece of a curved wall (ellipse arcs, sphere / torus / cylinder
  // patches). The geometric Shepard factor counts a point behind such an element by less
  // than `gap` as a point on the wall (it lies on the true wall to that accuracy).
  std::vector<double> gap;

  std::size_t size() const { return centre.size(); }
  void reserve(std::size_t n);
  void append(const BoundaryElements& other);

  // 2-D straight segment a -> b, fluid on the left.
  void add_segment(const VecD<D>& a, const VecD<D>& b);
  // 2-D arc from a to b (fluid on the left of a -> b) on a circle with signed curvature
  // kappa (> 0: fluid on the concave side, i.e. inside the circle). kappa = 0 is a segment.
  void add_arc(const VecD<D>& a, const VecD<D>& b, double kappa);
  // 3-D planar polygon (3 or 4 vertices, counter-clockwise seen from the fluid).
  void add_polygon(const VecD<D>* v, int count);

  // A piece of a curved wall, with the centre, unit normal and area (length) taken from the
  // true wall rather than from the vertices. 2-D: integrated as the circular arc a -> b with
  // curvature kappa (fluid on the left of a -> b); 3-D: integrated as the planar polygon v
  // (3 or 4 vertices on the wall, counter-clockwise seen from the fluid). `gap` as above.
  void add_curved_arc(const VecD<D>& a, const VecD<D>& b, const VecD<D>& centre,
                      const VecD<D>& normal, double length, double kappa, double gap);
  void add_curved_patch(const VecD<D>* v, int count, const VecD<D>& centre, const VecD<D>& normal,
                        double area, double gap);

  // Radius of a ball about centre[j] containing the whole element.
  double bounding_radius(std::size_t j) const;
};

// The dimension-specific members are explicit specializations (boundary_elements.cpp): calling
// one in the other dimension fails at link time.
template <>
void BoundaryElements<2>::add_segment(const VecD<2>& a, const VecD<2>& b);
template <>
void BoundaryElements<2>::add_arc(const VecD<2>& a, const VecD<2>& b, double kappa);
template <>
void BoundaryElements<3>::add_polygon(const VecD<3>* v, int count);
template <>
void BoundaryElements<2>::add_curved_arc(const VecD<2>& a, const VecD<2>& b, const VecD<2>& centre,
                                         const VecD<2>& normal, double length, double kappa,
                                         double gap);
template <>
void BoundaryElements<3>::add_curved_patch(const VecD<3>* v, int count, const VecD<3>& centre,
                                           const VecD<3>& normal, double area, double gap);

// ---- Generators --------------------------------------------------------------------------

// Polyline p0, p1, ... (fluid on the left of the direction of travel), each side split into
// equal segments no longer than about dx. `closed` joins the last point to the first.
BoundaryElements<2> polyline_elements(const std::vector<Vec2d>& points, double dx,
                                      bool closed = false);

// Circle as arcs of length about dx (vertices on the circle, normals at the arc midpoints,
// areas = arc lengths). The first vertex is at angle `start_angle` (radians).
BoundaryElements<2> circle_elements(const Vec2d& centre, double radius, double dx,
                                    bool fluid_inside, double start_angle = 0.0);

// Parallelogram origin + s e1 + t e2, s, t in [0, 1], as patches of side about dx; the fluid
// is on the side of e1 x e2.
BoundaryElements<3> rectangle_elements(const Vec3d& origin, const Vec3d& e1, const Vec3d& e2,
                                       double dx);

// Triangles as given (fluid on the side of (b - a) x (c - a)).
BoundaryElements<3> triangle_elements(const std::vector<std::array<Vec3d, 3>>& triangles);

}  // namespace curvsph
