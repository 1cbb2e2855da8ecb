#pragma once
// A circle (2-D): fluid inside (k = 1/R) or outside (k = -1/R).
#include <yaml-cpp/yaml.h>

#include "curvsph/geometry/shape_util.hpp"

namespace curvsph {

class CircleWall final : public Wall<2> {
 public:
  CircleWall(const Vec2d& center, double radius, FluidSide side);
  // u = polar angle of the foot about the centre, in (-pi, pi]. At the centre itself every
  // wall point is closest; the answer is the one at u = 0.
  WallPoint<2> closest(const Vec2d& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override { return radius_; }
  // Geometry, for discretisations (boundary elements).
  const Vec2d& center() const { return center_; }
  double radius() const { return radius_; }
  FluidSide side() const { return side_; }

 private:
  Vec2d center_;
  double radius_;
  FluidSide side_;
};

// YAML: {shape: circle, center: [x, y], radius: R, fluid: inside|outside}.
WallPtr<2> make_circle_wall(const YAML::Node& node, const std::string& file,
                            const std::string& key);

}  // namespace curvsph
