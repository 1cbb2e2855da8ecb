#pragma once
// An infinite plane (a straight line in 2-D); the fluid is on the side its normal points to.
#include <yaml-cpp/yaml.h>

#include "curvsph/geometry/wall.hpp"

namespace curvsph {

template <int D>
class PlaneWall final : public Wall<D> {
 public:
  // `normal` need not be unit; it must be non-zero.
  PlaneWall(const VecD<D>& point, const VecD<D>& normal);
  // Parameters: 2-D u along the tangent perp(n); 3-D (u, v) along the frame of n, both
  // measured from `point`.
  WallPoint<D> closest(const VecD<D>& x, const ParamSeed& seed = {}) const override;
  std::string describe() const override;
  double min_radius_of_curvature() const override;
  // Geometry, for discretisations (boundary elements): `normal` is unit.
  const VecD<D>& point() const { return point_; }
  const VecD<D>& normal() const { return normal_; }

 private:
  VecD<D> point_, normal_, t1_, t2_;
};

// YAML: {shape: plane, point: [..], normal: [..]}; `key` is the wall's path ("walls.0").
template <int D>
WallPtr<D> make_plane_wall(const YAML::Node& node, const std::string& file, const std::string& key);

}  // namespace curvsph
