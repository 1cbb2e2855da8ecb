#pragma once
// Boundary elements of the infinite walls (planes, infinite cylinders) cut to the part that
// bounds the fluid. Their generators clip them to the domain box only (wall_elements.hpp), so
// where two walls meet inside the box each runs on behind the other: a tank of three `plane`
// walls counted its floor behind the side walls and the sides below the floor, the corners
// twice, and its floor-corner particles sat at -0.47 rho g H (docs/geometry.md, note (e)).
//
// The fluid lies where every wall's signed distance is > 0 (the fill asks for that), so the
// part of a wall on the non-fluid side (signed distance < 0) of another wall bounds no fluid.
// Only walls whose sign really classifies space clip (clips_by_sign): planes, boxes, circles,
// ellipses, spheres, cylinders, tori and closed solids (Wall::closed_surface). An open wall's
// sign flips beyond its edges (a baffle, an open NURBS curve or mesh, one CAD face): it clips
// nothing. A closed obstacle does clip: the floor under a sphere sunk into it lies inside the
// sphere's solid; a sphere above the floor leaves the floor whole.
//
// Exactness: a vertex is kept where the other wall's signed distance is >= -tol, an edge that
// crosses the surface is cut at the root of that distance along the edge (regula falsi; exact
// for planes, whose distance is linear). A flat element cut by a plane is thus exact: 2-D
// segments clipped, 3-D polygons clipped by Sutherland & Hodgman, a result of more than 4
// vertices fanned into triangles. Against a curved wall the cut runs along the chord between
// the two edge crossings instead of the curve: the area error is the segment between chord and
// curve, c^3 kappa / 12 per chord c, about pi L^2 / 6 per cut curve for elements of side L
// whatever its radius (measured 4.96e-3 for a sphere sunk into a floor at L = 0.1, 0.2 % of
// the disc it cuts out; tests/boundary/test_wall_clip.cpp). A curved wall bulging through an
// element's edge between two vertices outside it is not seen (the element is kept whole): its
// reach into the element is at most the sagitta L^2 kappa / 8. A curved element (a cylinder patch,
// gap > 0) is clipped as its polygon; its area is the true area scaled by the clipped share of the
// polygon's and its centre is moved with the polygon's centroid (exact for a cut across the axis of
// a cylinder, where the share is that of the axial extent).
//
// The other walls are taken where they are, not as periodic images: an obstacle across a
// periodic seam cuts the floor on its own side of the seam only (draw it on both sides, as
// walls crossing a seam are drawn). Cost: one closest-point query per element and clipping
// wall (per vertex where the element lies within its own size of that wall), at set-up.
#include <vector>

#include "curvsph/boundary/integrals/boundary_elements.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// Whether the wall's elements run on past the region they bound (planes, infinite cylinders).
template <int D>
bool infinite_wall(const Wall<D>& body);

// Whether the wall's signed distance classifies every point of space as fluid side or not.
template <int D>
bool clips_by_sign(const Wall<D>& body);

// The part of `el` on the fluid side (signed distance >= -tol) of every wall of `others`.
template <int D>
BoundaryElements<D> clip_to_walls(const BoundaryElements<D>& el,
                                  const std::vector<const Wall<D>*>& others, double tol);

// The elements `el` of wall k of `walls` (an infinite wall's; others are returned unchanged)
// clipped by every other wall that clips_by_sign. Elements live in the walls' body frames:
// walls whose geometry moves (geometry/moving_wall.hpp) neither clip nor are clipped.
template <int D>
BoundaryElements<D> clip_by_other_walls(const BoundaryElements<D>& el, const WallSet<D>& walls,
                                        std::size_t k, double tol);

}  // namespace curvsph
