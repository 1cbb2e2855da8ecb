#pragma once
// An infinite circular cylinder (3-D): fluid inside (a pipe; k = 1/R around, 0 along the
// axis) or outside (an obstacle; k = 0 along the axis, -1/R around).
#include <yaml-cpp/yaml.h>

#include "curvsph/geometry/shape_util.hpp"

namespace curvsph {

class CylinderWall final : public Wall<3> {
 public:
  // `axis` need not be unit; it must be non-zero.
  CylinderWall(const Vec3d& point, const Vec3d& axis, double radius, FluidSide side);
  // u = angle about the axis in the frame orthonormal_frame(axis), in (-pi, pi];
  // v = coordinate along the axis from `point`. On the axis itself every point of the
  // circle is closest; the answer is the one at u = 0.
  WallPoint<3> closest(const Vec3d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override { return radius_; }
  // Geometry, for discretisations (boundary elements): `axis` is unit.
  const Vec3d& point() const { return point_; }
  const Vec3d& axis() const { return axis_; }
  double radius() const { return radius_; }
  FluidSide side() const { return side_; }

 private:
  Vec3d point_, axis_, e1_, e2_;
  double radius_;
  FluidSide side_;
};

// YAML: {shape: cylinder, point: [..], axis: [..], radius: R, fluid: inside|outside}.
WallPtr<3> make_cylinder_wall(const YAML::Node& node, const std::string& file,
                              const std::string& key);

}  // namespace curvsph
