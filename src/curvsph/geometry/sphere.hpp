#pragma once
// A sphere (3-D): fluid inside (k1 = k2 = 1/R) or outside (k1 = k2 = -1/R).
#include <yaml-cpp/yaml.h>

#include "curvsph/geometry/shape_util.hpp"

namespace curvsph {

class SphereWall final : public Wall<3> {
 public:
  SphereWall(const Vec3d& center, double radius, FluidSide side);
  // u = polar angle from +z in [0, pi], v = azimuth from +x about +z in (-pi, pi].
  // dir1, dir2 = the unit tangents of increasing u and v (any tangent pair is principal on
  // a sphere; at the poles the azimuth is 0). At the centre the answer is the foot at +z.
  WallPoint<3> closest(const Vec3d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override { return radius_; }
  // Geometry, for discretisations (boundary elements).
  const Vec3d& center() const { return center_; }
  double radius() const { return radius_; }
  FluidSide side() const { return side_; }

 private:
  Vec3d center_;
  double radius_;
  FluidSide side_;
};

// YAML: {shape: sphere, center: [..], radius: R, fluid: inside|outside}.
WallPtr<3> make_sphere_wall(const YAML::Node& node, const std::string& file,
                            const std::string& key);

}  // namespace curvsph
