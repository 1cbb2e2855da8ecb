#pragma once
// Ghost images at the edge where a flat face meets a curved wall of ANOTHER wall (an upright
// `cylinder` standing on a `plane` floor, a sphere cut by a plane through its centre). The
// flat-flat edges are flat_corners.hpp's and a CAD solid's own curved-planar edges are the
// multi-face ghosts' (ghosts.cpp); without this a curved wall and a plane of two walls get the
// single images only, and the support around their edge stays empty: sum V W at 0.2 h from
// both an upright cylinder's side and its floor was 0.86 against 1.00 (tests/boundary/
// test_plane_edges.cpp, mirror_beta, R = 2.25 h).
//
// Multiple mirroring across the plane (the 90-degree case of flat_corners.hpp, the box's
// double reflection) is exact when the curved wall is mirror-symmetric about the plane near
// the particle: then the fluid reflected across the plane is bounded by the same wall, and the
// curved image of the reflected particle x_A is the curved image of x reflected across the
// plane. Condition checked (the wall itself answers, whatever its shape): the closest point of
// x_A is the reflection of x's closest point (foot within 1e-9 of the support, normal within
// 1e-9, the same distance and principal curvatures, so the ghost map gives the same depth and
// volume weight). Where it fails (a cylinder leaning on the plane, a sphere off it) no image is
// made: the single images alone, as before.
#include <optional>

#include "curvsph/boundary/ghost/flat_corners.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

template <int D>
struct PlaneEdgeImage {
  VecD<D> x;     // the curved image reflected across the plane
  VecD<D> foot;  // its foot on the plane
  double depth;  // its distance behind the plane, >= 0
};

// The corner image for particle x whose single image across the curved wall `w` is `ghost`
// (closest point `p`), across the flat face A of another wall; none where the condition above
// fails or the image lies `support` or more behind the plane (out of every fluid support).
template <int D>
std::optional<PlaneEdgeImage<D>> plane_edge_image(const Wall<D>& w, const VecD<D>& x,
                                                  const WallPoint<D>& p, const VecD<D>& ghost,
                                                  const FlatFace<D>& A, double support);

}  // namespace curvsph
