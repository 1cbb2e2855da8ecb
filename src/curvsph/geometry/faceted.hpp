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
  // Whether a face within `reach` of x may reach behind the plane through `foot` with normal
  // `n` (into the fluid) by more than 1e-3 reach: a cheap conservative test (bounding boxes)
  // that lets the convex edges' shares (boundary/ghost/convex_edges.hpp) skip the faces'
  // query where no face recedes behind a planar face; true when unknown.
  virtual bool may_reach_behind(const VecD<D>& /*x*/, double /*reach*/, const VecD<D>& /*foot*/,
                                const VecD<D>& /*n*/) const {
    return true;
  }
};

}  // namespace curvsph
