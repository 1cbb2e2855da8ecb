#pragma once
// A closed CAD shell or solid as ONE wall (docs/geometry.md "CAD solids"): the faces (trimmed
// NURBS walls, one per B-rep face) answer the closest point, the solid decides the side.
//
// closest(x): the faces are visited nearest bounding box first and the visit stops when the
// next box is farther than the best answer so far, so a point usually queries one or two faces.
// The nearest face answers. Its sign (its normal at the foot) is right wherever the foot lies
// inside the face; a foot on an edge or a vertex is shared by the faces meeting there (their
// feet coincide). There:
//  - the sign is the one the meeting faces agree on, and when they disagree (a sharp edge,
//    where one face's normal sees the point on the wrong side) the solid classifier's
//    (OpenCASCADE's BRepClass3d_SolidClassifier, ray parity over the faces) decides;
//  - if the faces' normals differ (a sharp edge or corner), the normal is along foot -> point
//    (into the fluid) and the curvatures are 0, as the box's edges and corners give; on a
//    tangent (G1) junction, a pipe's straight part meeting its bend, the nearest face answers
//    as it is.
#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "curvsph/cad/trimmed_face_wall.hpp"
#include "curvsph/geometry/faceted.hpp"
#include "curvsph/geometry/shape_util.hpp"

class TopoDS_Shape;

namespace curvsph::cad {

class CadSolidWall : public Wall<3>, public MultiFace<3> {
 public:
  // `shape` holds the closed shells (solids or shells) whose faces are `faces`, in metres
  // after `scale`; `side`: where the fluid is relative to the closed shell.
  CadSolidWall(const TopoDS_Shape& shape, std::vector<std::shared_ptr<const TrimmedFaceWall>> faces,
               curvsph::FluidSide side, double scale, std::string label);
  ~CadSolidWall() override;

  WallPoint<3> closest(const Vec3d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override;
  double distance_lower_bound(const Vec3d& x) const override;
  bool closed_surface() const override { return true; }
  // Every face whose box is within `reach`, answering alone (faceted.hpp), nearest box first.
  int face_points_near(const Vec3d& x, double reach, WallPoint<3>* out, int max) const override;
  // From the faces' boxes: a box within reach with a corner behind the plane (faceted.hpp).
  bool may_reach_behind(const Vec3d& x, double reach, const Vec3d& foot,
                        const Vec3d& n) const override;

  // +1: x inside the closed shell, -1: outside, 0: on it (within the shape's tolerance).
  // The classifier of OpenCASCADE; independent of the faces' normals.
  int classify(const Vec3d& x) const;
  curvsph::FluidSide side() const { return side_; }
  const std::vector<std::shared_ptr<const TrimmedFaceWall>>& faces() const { return faces_; }

 private:
  struct Occ;  // the solids, kept out of this header
  std::unique_ptr<Occ> occ_;
  std::vector<std::shared_ptr<const TrimmedFaceWall>> faces_;
  std::vector<Eigen::AlignedBox3d> boxes_;  // of every face, in metres, grown by the tolerance
  curvsph::FluidSide side_;
  double scale_;
  double length_;  // diagonal of the whole bounding box: the scale of the tie tolerance
  std::string label_;
};

// Whether every shell of `shape` is closed (each edge shared by two faces) and there is one.
bool is_closed_shell(const TopoDS_Shape& shape);

}  // namespace curvsph::cad
