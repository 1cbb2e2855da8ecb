#pragma once
// Boundary elements from the walls of a case (DESIGN.md §4, boundary integrals): every wall
// type of geometry/ discretised at spacing about dx, normals into the fluid.
//
//  2-D  plane    the line clipped to the domain box, equal segments
//       box      its 4 sides (fluid inside: counter-clockwise; outside: clockwise)
//       circle   circular arcs (exact: vertices, centres on the circle, areas = arc lengths)
//       ellipse  pieces of equal arc length (by Gauss-Legendre quadrature of |C'|): vertices
//                and centres on the ellipse, normal = the ellipse's normal at the centre,
//                length = the true arc length; integrated as the circular arc through the
//                two vertices and the centre (gap = its largest distance from the ellipse)
//  3-D  plane    square patches covering the plane's intersection with the domain box
//                (exact for planes normal to an axis; an oblique plane keeps the patches of
//                its bounding rectangle whose centre lies in the domain)
//       box      its 6 faces as square patches
//       cylinder clipped to the domain's extent along the axis (the projection of the
//                domain box on it), quads in (angle, axial coordinate)
//       sphere   latitude bands of height about dx, all split into the same number of
//                quads (about dx along the equator, narrower towards the poles; triangles at
//                the poles). The same count in every band keeps the polyhedron watertight:
//                bands with their own counts (T-junctions at the seams) gave on-wall gamma
//                errors up to 0.5 at seam vertices and 0.03 elsewhere.
//       torus    quads in (poloidal, toroidal) angles, about dx on the tube and on the mean
//                circle of the torus
//  Curved patches: vertices on the surface (planar, by symmetry: rectangles or isosceles
//  trapezoids), centre = the surface point at the middle of the parameter cell, normal = the
//  surface normal there, area = the exact area of the curved cell; integrated as the planar
//  polygon of the vertices (gap = the surface's largest distance from it).
//
// Extension point (how a NURBS wall plugs in): one free function per wall type
// `bool discretize_X(const Wall<D>&, double dx, const Bounds&, BoundaryElements<D>&)` that
// dynamic_casts the wall and returns false when it is not its type, plus one line in the
// table `discretizers<D>()` in wall_elements.cpp — the only place that knows the wall types.
// Geometry stays independent of boundary integrals (walls expose their parameters only).
#include <Eigen/Geometry>

#include "curvsph/boundary/integrals/boundary_elements.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

template <int D>
using Bounds = Eigen::AlignedBox<double, D>;

// Elements of one wall. `bounds` clips infinite walls (plane, cylinder); they throw
// std::invalid_argument when it is empty. Throws std::invalid_argument for dx <= 0 or a
// wall type nobody discretises.
template <int D>
BoundaryElements<D> elements_from_wall(const Wall<D>& wall, double dx, const Bounds<D>& bounds);

// All walls of a set, concatenated in the set's order.
template <int D>
BoundaryElements<D> elements_from_walls(const WallSet<D>& walls, double dx,
                                        const Bounds<D>& bounds);

// Arc length of the ellipse (a cos u, b sin u) between eccentric angles u0 and u1
// (Gauss-Legendre, pieces of at most 1/16 rad; relative accuracy near round-off).
double ellipse_arc_length(double a, double b, double u0, double u1);

}  // namespace curvsph
