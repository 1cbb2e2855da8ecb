#pragma once
// Faceted walls: every face flat, meeting at sharp corners (a polygon from a degree-1 NURBS
// curve). Ghosts mirror across every face near a particle and add the multiple images of
// concave corners (boundary/ghost/facet_images.hpp); a wall that is not faceted answers with
// its closest point alone.
#include "curvsph/core/types.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// A flat face: its end points (2-D) and its normal into the fluid.
template <int D>
struct WallFacet {
  VecD<D> a = VecD<D>::Zero();
  VecD<D> b = VecD<D>::Zero();
  VecD<D> normal = VecD<D>::Zero();
};

template <int D>
class Faceted {
 public:
  virtual ~Faceted() = default;
  // Writes the faces whose distance to x is below `reach` into out[0 .. max) and returns how
  // many; -1 when this wall is not faceted after all (a NURBS curve of degree > 1).
  virtual int facets_near(const VecD<D>& x, double reach, WallFacet<D>* out, int max) const = 0;
};

// Walls made of several faces meeting at edges (a closed CAD solid): the closest point on each
// face within `reach` of x, each face answering alone (its own normal, distance and
// curvatures; a foot on the face's boundary where x projects beyond it). Ghosts mirror across
// every face onto which x projects and add the double images of perpendicular edges.
template <int D>
class MultiFace {
 public:
  virtual ~MultiFace() = default;
  virtual int face_points_near(const VecD<D>& x, double reach, WallPoint<D>* out,
                               int max) const = 0;
};

}  // namespace curvsph
