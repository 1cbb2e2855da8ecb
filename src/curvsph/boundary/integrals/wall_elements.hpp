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
//       nurbs_curve  the same per smooth piece: the curve is cut at its crease knots
//                (interior multiplicity >= degree: every interior knot of a degree-1
//                polyline), each piece into elements of equal arc length about dx; a straight
//                piece gives exact segments (a wedge of degree 1: exact corners), an open
//                curve ends at its end points (the singular part: the angle it subtends)
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
//       nurbs_surface  curved quads on the tensor grid of nurbs::sample_surface (equal chord
//                length of iso-curves, about dx), every crease knot (interior multiplicity >=
//                degree) a grid line; area = int |S_u x S_v| over the cell (Gauss-Legendre
//                8 x 8 between knots); fluid on the front or back as the wall says
//       trimesh  (STL) the triangles, each split into k^2 similar ones (pieces of about
//                dx^2 / 2 and no longer than about 2 dx), oriented by the wall's own normal.
//                Neighbours with another k meet at T-junctions on their common straight edge:
//                the elements cover the mesh exactly (area = the mesh's), which is what the
//                solid angles need; exact flat elements (gap 0)
//       cad      (trimmed faces) cells of about dx in the face's own (u, v) rectangle; cells
//                clear of the trim loops kept whole (curved quads) or dropped, cells a loop
//                touches clipped to the face (the loop, sampled at dx / 4 along its edges,
//                clipped to the cell) and fanned into triangles about the clipped polygon's
//                centroid, area = int |S_u x S_v| over each (collapsed Gauss-Legendre 8 x 8);
//                a cell that the face covers whole and on which the surface is flat and
//                affine (a plane face's border cells: the loop runs along its sides) stays
//                one patch, so a CAD box has the `box` wall's elements. Faces sharing an edge share
//                its samples (edge parameter): they meet vertex to vertex. A cell that a hole's
//                loop crosses, or whose part is not star-shaped: the loop's chain closed along the
//                cell's side, ear-clipped. A cell crossed by several loops or twice is split in
//                four, three times, then kept or dropped by its centre. A point on a curved rim
//                between two samples lies outside the elements by the chord's sagitta, (dx / 4)^2 /
//                (8 R)
//  Curved patches: vertices on the surface (planar, by symmetry, on the analytic surfaces:
//  rectangles or isosceles trapezoids; a NURBS cell's four corners need not be coplanar),
//  centre = the surface point at the middle of the parameter cell, normal = the surface
//  normal there, area = the exact area of the curved cell; integrated as the polygon of the
//  vertices (gap = the largest distance of the surface and the vertices from its plane).
//  Their gamma error near a curved face is that of the chords, O(kappa dx^2 / h): measured
//  4.3e-3 near the top of a NURBS bump of radius of curvature 5.8 h (h = 2 dx).
//
// Extension point: one free function per wall type (the free-form walls' in
// wall_elements_freeform.cpp and wall_elements_cad.cpp, declared in wall_elements_freeform.hpp)
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
