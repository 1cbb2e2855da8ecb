#pragma once
// A B-rep face as a wall: the NURBS surface of the face, trimmed by the face's boundary.
// The closest point must lie on the face as trimmed: the untrimmed closest point is kept
// when OpenCASCADE's face classifier puts it inside the face (or on its boundary); otherwise
// the answer is the closest point on the face's boundary edges. (Limitation: a second local
// minimum of the untrimmed surface inside the trimmed region that is nearer than the
// boundary is not searched for; for the cylinders, tori, planes and gently curved patches of
// CAD walls the distance grows monotonically away from the untrimmed foot, so this holds.)
#include <TopoDS_Face.hxx>
#include <array>
#include <memory>
#include <vector>

#include "curvsph/geometry/nurbs_surface_wall.hpp"

class Geom_Surface;
class Geom_Curve;

namespace curvsph::cad {

class TrimmedFaceWall : public Wall<3> {
 public:
  TrimmedFaceWall(std::shared_ptr<const NurbsSurfaceWall> surface, const TopoDS_Face& face,
                  double scale, std::string label);
  ~TrimmedFaceWall() override;

  // Planes and cylinders answer in closed form (elementary_face.hpp), other surfaces from the
  // NURBS conversion; closest_nurbs always from the NURBS conversion (the general path).
  WallPoint<3> closest(const Vec3d& x, const ParamSeed& seed = {}) const override;
  WallPoint<3> closest_nurbs(const Vec3d& x, const ParamSeed& seed = {}) const;
  std::string describe() const override { return label_ + ": " + surf_->describe(); }
  double min_radius_of_curvature() const override { return surf_->min_radius_of_curvature(); }
  const NurbsSurfaceWall& surface_wall() const { return *surf_; }
  const TopoDS_Face& face() const;

  // The face in its own parametrisation (OpenCASCADE's surface of the face, lengths times the
  // scale), for boundary elements: the (u, v) bounds of the face {u0, u1, v0, v1}, the point
  // and first derivatives, and the trim loops (every wire, edges in wire order, each edge's
  // curve on the surface sampled so that consecutive points are at most `spacing` apart in
  // 3-D) as closed polygons in (u, v), the last point not repeated.
  std::array<double, 4> uv_bounds() const;
  void eval(double u, double v, Vec3d& p, Vec3d& su, Vec3d& sv) const;
  std::vector<std::vector<std::array<double, 2>>> trim_loops(double spacing) const;

 private:
  WallPoint<3> answer(const Vec3d& x, const ParamSeed& seed, bool allow_elementary) const;

  struct Occ;  // OpenCASCADE handles, kept out of this header
  std::shared_ptr<const NurbsSurfaceWall> surf_;
  std::unique_ptr<Occ> occ_;
  double scale_;
  std::string label_;
};

}  // namespace curvsph::cad
