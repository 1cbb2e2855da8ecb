#pragma once
// A 3-D wall made of triangles (STL import): closest point on triangles found through a BVH,
// normal = the face normal inside a triangle and the angle-weighted pseudo-normal on edges and
// vertices (Baerentzen & Aanaes 2005: its sign is the correct inside/outside test), curvature 0.
// Triangles are oriented counter-clockwise seen from outside (STL convention); `fluid`
// says whether the fluid is outside (normals as given) or inside (flipped).
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

#include "curvsph/geometry/bvh.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

class TriMeshWall : public Wall<3> {
 public:
  enum class Side { outside, inside };
  TriMeshWall(std::vector<Vec3d> vertices, std::vector<std::array<int, 3>> triangles, Side fluid);

  WallPoint<3> closest(const Vec3d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override;

  std::size_t triangle_count() const { return tris_.size(); }
  const std::vector<Vec3d>& vertices() const { return v_; }
  const std::vector<std::array<int, 3>>& triangles() const { return tris_; }

 private:
  std::vector<Vec3d> v_;
  std::vector<std::array<int, 3>> tris_;
  std::vector<Vec3d> face_n_;
  std::vector<Vec3d> vert_n_;                 // angle-weighted pseudo-normals
  std::vector<std::array<Vec3d, 3>> edge_n_;  // per triangle edge (i, i+1): sum of both faces
  Bvh<3> bvh_;
  double sign_;
};

}  // namespace curvsph
