#pragma once
// The closest point of a CAD face's surface in closed form where OpenCASCADE says the surface
// is a plane or a circular cylinder (GeomAbs_Plane, GeomAbs_Cylinder: what STEP files store
// for flat and round faces). TrimmedFaceWall answers from it instead of its NURBS conversion,
// whose global projection (nurbs/surface_projection.cpp, a branch-and-bound over the Bezier
// patches) was 77 % of a CAD cylinder run's time (perf, the cad_at_rest cylinder with
// mirror_beta ghosts; the hull bounds close in slowly for a point inside a concave cylinder,
// where much of the surface is nearly equidistant). Same answer as the NURBS path: foot,
// signed distance, normal into the fluid, principal curvatures (k > 0 concave from the fluid,
// k1 >= k2) and directions (tests/cad/test_elementary_face.cpp against it).
#include <Geom_Surface.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <optional>

#include "curvsph/geometry/wall.hpp"

namespace curvsph::cad {

class ElementaryFace {
 public:
  // nullopt unless `surface` is a plane or a cylinder. `fluid_sign`: +1 where the surface's
  // own normal (the plane's axis, the cylinder's outward radius) points into the fluid, -1
  // where away; `scale`: metres per unit of the surface.
  static std::optional<ElementaryFace> make(const Handle(Geom_Surface) & surface, double scale);
  void set_fluid_sign(double s) { sign_ = s; }

  // The untrimmed surface's closest point to x (metres); false on a cylinder's axis (every
  // point of a circle is closest: the caller's general path answers).
  bool closest(const Vec3d& x, WallPoint<3>& p) const;
  // The surface's own parameters (u, v) of a point of it (metres), for the trimming test.
  void parameters(const Vec3d& foot, double& u, double& v) const;
  // The surface's own normal at a foot (the sign convention of set_fluid_sign).
  Vec3d own_normal(const Vec3d& foot) const;

 private:
  bool cylinder_ = false;
  gp_Pln plane_;
  gp_Cylinder cyl_;
  Vec3d origin_, axis_;  // metres; the plane's normal or the cylinder's axis (unit)
  double radius_ = 0;    // metres
  double scale_ = 1, sign_ = 1;
};

}  // namespace curvsph::cad
