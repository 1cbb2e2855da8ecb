#pragma once
// The faces' partition of unity at the sharp edges of a wall of several faces (a CAD solid, an
// STL mesh: geometry/faceted.hpp's MultiFace), in the manner of the convex polygon corners
// (facet_images.hpp) and the box obstacles (convex_box.hpp).
//
// A particle x that projects onto a face X (at distance d < 2h) has its image y at depth D_X
// below X's foot (y = x - 2 d n_X for a planar face; the ghost map's depth for a curved one,
// whose image keeps the map's volume factor beta times its share). Near an edge where the solid is
// convex seen from the fluid, y is also the image of the fluid point that mirrors onto it across
// the other face, and each single image at full volume covers the solid there two or three times
// (kernel sums up to 1.64 at the middle of a CAD box's edge, docs/geometry.md). The image is
// weighted by X's share of the solid at y,
//   s_X(y) = f(D_X) / sum_Z f(D_Z(y)),  f(D) = (1 - D/2h)^2 / D^2 (0 beyond 2h),
// the sum over X and the faces Z, planar or curved, that are y's sources across a convex edge
// with X: Z's foot of y lies behind X's tangent plane, y lies behind Z and projects onto Z at
// distance D_Z(y) < 2h, and its reflection across Z's tangent plane lies in the fluid (the
// source itself for the mirror and mirror_beta maps; for density_preserving, whose source lies
// at another distance, a proxy) (`in_fluid` asks every
// wall: a re-entrant neighbour's reflection can land in the solid, and a face lying on another
// wall's, a box standing on a floor, takes no share). Each such source projects onto Z and
// mirrors onto y, so the shares of y over its sources sum to 1: the solid is covered once,
// pointwise. Where y has no other source (a face's middle, a concave edge) the share is 1 and
// the image is the plain mirror as before (at concave edges flat_corners.hpp cuts the
// overlaps at the bisector and adds the corner images). Curved faces take no part: their
// images keep their volume.
#include <functional>

#include "curvsph/geometry/faceted.hpp"

namespace curvsph {

// X's share of its image y at depth d below X's foot y + d n (n: X's normal there, into the
// fluid) among the faces of `faces` that have y as an image; `in_fluid(r)`: whether r is a
// fluid point (outside every wall).
template <int D>
double edge_share(const MultiFace<D>& faces, const VecD<D>& y, const VecD<D>& n, double d,
                  double support, const std::function<bool(const VecD<D>&)>& in_fluid);

}  // namespace curvsph
