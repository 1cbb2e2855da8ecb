#pragma once
// Ghost images around a box with the fluid outside (an obstacle): its edges and corners are
// convex seen from the fluid (the solid's angle 90 degrees), and the closest point alone
// covers the solid near them up to three times (an edge, 2-D corner: a particle that projects
// onto face A mirrors across A, one onto B across B, one beyond both through the edge line;
// kernel sums up to 1.63 at the middle of an edge, docs/geometry.md).
//
// The construction is facet_images.hpp's for convex polygon corners, in any dimension. A
// point y of the solid box is the image of one fluid point per face Z, its reflection across
// Z's plane (outside the box: it is convex), which is a fluid point unless another wall holds
// it (a box standing on a floor: the reflections across its bottom face lie below the floor).
// The reflection of a particle x across face X is
// weighted by X's share of the solid at its image y,
//   s_X(y) = f(D_X(y)) / sum_Z f(D_Z(y)),  f(D) = (1 - D/2h)^2 / D^2 (0 beyond 2h),
// D_Z(y) the distance from y to face Z (for y in the box: to Z's plane), the sum over the
// faces whose reflection of y is a fluid point (X's is: x), so that the shares
// sum to 1 at every solid point: the solid is covered once, pointwise (a partition of unity;
// the share is the ghost's beta, a share of its source's volume). The edges' and corners'
// own images (rotation by pi about an edge line, the point image through a vertex) have no
// share: at 90 degrees the faces' reflections cover the solid alone (facet_images.hpp's
// vertex factor is 0 for solid angles of 90 degrees and more). A particle whose reflection
// leaves the box (beyond a thin box's far face) has no share of it but keeps it, if it
// projects onto the face, as a guard of no volume, and one that projects onto no face keeps
// its closest-point image (the rotation about the edge, the point image through the vertex)
// as a guard: the contact layer and the wall force read a particle's distance to its wall
// through its own single images (ghost_boundary.cpp).
#include <functional>

#include "curvsph/boundary/ghost/facet_images.hpp"

namespace curvsph {

// The images of x (outside the box [lo, hi]) within `support` of the box; writes at most
// `max` and returns how many. `in_fluid(r)`: whether r is a fluid point (outside every wall). The
// single images' `normal` is the face's (outward from the box, into the fluid); a guard through an
// edge or a vertex has foot -> x.
template <int D>
int box_outside_images(const VecD<D>& x, const VecD<D>& lo, const VecD<D>& hi, double support,
                       const std::function<bool(const VecD<D>&)>& in_fluid, FacetImage<D>* out,
                       int max);

}  // namespace curvsph
