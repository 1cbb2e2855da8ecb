#pragma once
// A 3-D wall made of triangles (STL import): closest point on triangles found through a BVH,
// normal = the face normal inside a triangle and the angle-weighted pseudo-normal on edges and
// vertices (Baerentzen & Aanaes 2005: its sign is the correct inside/outside test on a closed,
// consistently oriented mesh), principal curvatures estimated per vertex at construction
// (mesh_curvature.hpp) and interpolated barycentrically over the triangle at the foot point.
// Triangles are oriented counter-clockwise seen from outside (STL convention); `fluid`
// says whether the fluid is outside (normals as given) or inside (flipped).
//
// Smooth faces: the triangles are grouped across edges whose faces turn by less than the
// feature angle (a box's 12 triangles make 6 faces, a tessellated sphere one). A mesh of
// several faces is a MultiFace (geometry/faceted.hpp), as a CAD solid: each face answers
// alone, so ghosts mirror across every face a particle projects onto and add the double images
// of the perpendicular edges (boundary/ghost/ghosts.cpp). A face whose triangles are coplanar
// answers with curvature 0 exactly (the flat faces of those edge images).
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "curvsph/geometry/bvh.hpp"
#include "curvsph/geometry/faceted.hpp"
#include "curvsph/geometry/mesh_curvature.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

class TriMeshWall : public Wall<3>, public MultiFace<3> {
 public:
  enum class Side { outside, inside };
  // Edges whose faces turn by more than this are creases: the curvature estimate does not
  // reach across them (30 degrees, the usual feature angle of mesh tools such as VTK's).
  static constexpr double kFeatureAngle = 30.0 * 3.14159265358979323846 / 180.0;

  TriMeshWall(std::vector<Vec3d> vertices, std::vector<std::array<int, 3>> triangles, Side fluid);

  WallPoint<3> closest(const Vec3d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override;
  // The closest point of every smooth face within `reach` of x (none for a mesh of one face:
  // closest() answers there).
  int face_points_near(const Vec3d& x, double reach, WallPoint<3>* out, int max) const override;

  std::size_t triangle_count() const { return tris_.size(); }
  // Smooth faces: how many, and the face of every triangle.
  int face_count() const { return faces_; }
  const std::vector<int>& face_of() const { return face_of_; }
  const std::vector<Vec3d>& vertices() const { return v_; }
  const std::vector<std::array<int, 3>>& triangles() const { return tris_; }

 private:
  std::vector<Vec3d> v_;
  std::vector<std::array<int, 3>> tris_;
  std::vector<Vec3d> face_n_;
  std::vector<Vec3d> vert_n_;                 // angle-weighted pseudo-normals
  std::vector<std::array<Vec3d, 3>> edge_n_;  // per triangle edge (i, i+1): sum of both faces
  MeshCurvature curv_;
  Bvh<3> bvh_;
  double sign_;
  std::vector<int> face_of_;        // smooth face of every triangle
  std::vector<Vec3d> face_normal_;  // per smooth face: its normal if planar, else zero
  int faces_ = 0;
  // The WallPoint of foot `foot` on triangle t (feature f of closest_on_triangle, distance d).
  WallPoint<3> answer(const Vec3d& x, int t, int f, const Vec3d& foot, double d) const;
};

}  // namespace curvsph
